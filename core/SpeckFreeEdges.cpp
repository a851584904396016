#include "core/SpeckFreeEdges.h"

#include <algorithm>

namespace omnitune {

int binaryStep(int whiteLevel)
{
    const int white = binaryWhiteLevel(whiteLevel);
    return white == 0 ? 255 : std::min(white, 255 - white);
}

EdgeOptions speckFreeCannyOptions(const EdgeOptions& options)
{
    EdgeOptions out = options;
    if (!options.dropSpecks || options.input != EdgeInput::Binary) return out;
    // A straight border is 4 steps (|dx| = 1 + 2 + 1 steps); one below keeps it.
    const int borderGradient = 4 * binaryStep(options.whiteLevel);
    out.cannyLow = std::max(out.cannyLow, borderGradient - 1);
    out.cannyHigh = std::max(out.cannyHigh, borderGradient - 1);
    return out;
}

OpenCvHoughOptions speckFreeHoughOptions(const OpenCvHoughOptions& options, const EdgeOptions& edges)
{
    OpenCvHoughOptions out = options;
    if (!options.dropSpecks || edges.input != EdgeInput::Binary) return out;
    out.cannyHigh = std::max(out.cannyHigh, 4.0 * binaryStep(edges.whiteLevel) - 1.0);
    return out;
}

}  // namespace omnitune
