#include "calib/fit/FitFrames.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

FitFrames readFitFrames(FrameSource& source, int count, Progress* progress)
{
    FitFrames out;
    const int total = source.frameCount();
    const bool spread = source.isSeekable() && total > 0;
    const int wanted = spread ? std::min(count, total) : count;
    for (int i = 0; i < wanted; ++i) {
        if (progress && progress->isCancelRequested()) {
            out.error = FitError{FitErrorKind::Cancelled, "reading frames cancelled"};
            return out;
        }
        // Evenly over the source, first and last frame included.
        const int index = !spread ? FrameSource::kNext : wanted == 1 ? 0 : int(std::lround(double(i) * (total - 1) / (wanted - 1)));
        Frame frame;
        if (const auto err = source.read(index, frame)) {
            if (err->kind == FrameErrorKind::OutOfRange) break;  // a source shorter than asked
            out.warnings.push_back(err->toString() + "; frame skipped");
            continue;
        }
        out.images.push_back(frame.image);
        out.indices.push_back(frame.index);
        if (progress) progress->update(100.0 * (i + 1) / wanted);
    }
    if (out.images.empty())
        out.error = FitError{FitErrorKind::BadInput, "no frame of " + source.description() + " could be read"};
    return out;
}

}  // namespace omnitune
