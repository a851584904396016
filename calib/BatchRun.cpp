#include "BatchRun.h"

namespace omnitune {

BatchSummary runBatch(FrameSource& source, Pipeline& pipeline, const BatchCallback& onFrame, Progress* progress,
                      bool wantStageImages)
{
    BatchSummary summary;
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
            result = PipelineResult{};
            result.error = err->toString();
            ++summary.failed;
            onFrame(i, nullptr, result);
        } else {
            pipeline.process(frame.image, frame.format, result, wantStageImages);
            ++(result.ok() ? summary.processed : summary.failed);
            onFrame(i, &frame, result);
        }
        if (progress && count > 0) progress->update(100.0 * (i + 1) / count);
    }
    return summary;
}

}  // namespace omnitune
