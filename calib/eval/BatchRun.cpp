#include "calib/eval/BatchRun.h"

namespace omnitune {

BatchSummary runBatch(FrameSource& source, Pipeline& pipeline, const BatchCallback& onFrame, Progress* progress,
                      bool wantStageImages)
{
    BatchSummary summary;
    constexpr int kMaxConsecutiveFailures = 50;
    int consecutiveFailures = 0;
    const int count = source.frameCount();
    Frame frame;
    PipelineResult result;
    for (int i = 0; count < 0 || i < count; ++i) {
        if (progress && progress->isCancelRequested()) {
            summary.cancelled = true;
            break;
        }
        const auto err = source.read(source.isSeekable() ? i : FrameSource::kNext, frame);
        if (err && err->kind == FrameErrorKind::OutOfRange) break;  // the end of a stream
        ++summary.frames;
        if (err) {
            // A stream of unknown length that keeps failing would otherwise never end.
            if (count < 0 && ++consecutiveFailures >= kMaxConsecutiveFailures) break;
            result = PipelineResult{};
            result.error = err->toString();
            ++summary.failed;
            onFrame(i, nullptr, result);
        } else {
            try {
                pipeline.process(frame.image, frame.format, result, wantStageImages);
            } catch (const std::exception& e) {  // a bad frame is reported, never fatal
                result = PipelineResult{};
                result.error = e.what();
            }
            ++(result.ok() ? summary.processed : summary.failed);
            consecutiveFailures = 0;
            onFrame(i, &frame, result);
        }
        if (progress && count > 0) progress->update(100.0 * (i + 1) / count);
    }
    return summary;
}

}  // namespace omnitune
