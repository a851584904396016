#pragma once
// The frames a geometry fit uses, taken from a source: `count` frames spread evenly over a
// seekable source with a known length (so a tour's different poses are seen), else the first
// `count`. Unreadable frames are skipped with a warning line each.
#include "calib/fit/FitError.h"
#include "calib/source/FrameSource.h"
#include "core/Progress.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct FitFrames {
    std::vector<cv::Mat> images;       // as the source delivers them (BGR or UYVY)
    std::vector<int> indices;          // which frames
    std::vector<std::string> warnings; // one line per frame skipped
    std::optional<FitError> error;     // no frame could be read, or cancelled

    bool ok() const { return !error.has_value(); }
};

FitFrames readFitFrames(FrameSource& source, int count, Progress* progress = nullptr);

}  // namespace omnitune
