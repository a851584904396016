#pragma once
// Runs the pipeline over a whole frame source: omnitune-detect, omnitune-eval and the GUI's
// "apply to whole session" share this loop. A frame that cannot be read or processed is
// reported through the callback (result.error set) and skipped, never fatal.
#include "calib/source/FrameSource.h"
#include "core/Pipeline.h"
#include "core/Progress.h"

#include <functional>

namespace omnitune {

struct BatchSummary {
    int frames = 0;     // frames visited
    int processed = 0;  // frames the pipeline processed without error
    int failed = 0;     // frames skipped (unreadable, wrong size, ...)
    bool cancelled = false;
};

// `frame` is null when the frame could not be read; `result.error` then says why.
using BatchCallback = std::function<void(int index, const Frame* frame, const PipelineResult& result)>;

BatchSummary runBatch(FrameSource& source, Pipeline& pipeline, const BatchCallback& onFrame,
                      Progress* progress = nullptr, bool wantStageImages = false);

}  // namespace omnitune
