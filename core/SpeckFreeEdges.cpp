#include "core/SpeckFreeEdges.h"

#include <algorithm>

namespace omnitune {

int binaryStep(int whiteLevel)
{
    const int white = binaryWhiteLevel(whiteLevel);
    return white == 0 ? 255 : std::min(white, 255 - white);
}

namespace {

// Just below a straight border's gradient: 4 steps (|dx| = 1 + 2 + 1 steps), less one.
int speckFreeThreshold(int whiteLevel) { return 4 * binaryStep(whiteLevel) - 1; }

}  // namespace

EdgeOptions speckFreeCannyOptions(const EdgeOptions& options)
{
    EdgeOptions out = options;
    if (!options.dropSpecks || options.input != EdgeInput::Binary) return out;
    out.cannyLow = std::max(out.cannyLow, speckFreeThreshold(options.whiteLevel));
    out.cannyHigh = std::max(out.cannyHigh, speckFreeThreshold(options.whiteLevel));
    return out;
}

OpenCvHoughOptions speckFreeHoughOptions(const OpenCvHoughOptions& options, const EdgeOptions& edges)
{
    OpenCvHoughOptions out = options;
    if (!options.dropSpecks || edges.input != EdgeInput::Binary) return out;
    out.cannyHigh = std::max(out.cannyHigh, double(speckFreeThreshold(edges.whiteLevel)));
    return out;
}

}  // namespace omnitune
