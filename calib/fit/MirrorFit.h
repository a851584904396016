#pragma once
// Centre and rim, then the robot body, fitted from frames and written into a config: what
// `omnitune-calibrate rim` and the window's Camera > Find mirror centre and rim both do. Frames
// of another size than the config's first get a provisional geometry (calib/config/
// ProvisionalGeometry.h), so every radius-like value follows the new camera before the fit
// replaces centre and radii.
#include "calib/fit/BodyFit.h"
#include "calib/fit/FitError.h"
#include "calib/fit/RimFit.h"
#include "core/Config.h"
#include "core/Progress.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct MirrorFitResult {
    Config config;                  // `start` with the fit applied; meaningful only when ok()
    RimFit rim;
    std::optional<BodyFit> body;    // empty when the body was not fitted
    std::vector<std::string> adapted;  // what the provisional geometry changed first (other frame size)
    std::optional<FitError> error;

    bool ok() const { return !error.has_value(); }
};

// `fitBodyToo` false keeps the config's inner radius (one frame is enough then).
MirrorFitResult fitMirror(const std::vector<cv::Mat>& frames, const Config& start, const RimFitOptions& options = {},
                          bool fitBodyToo = true, Progress* progress = nullptr);

}  // namespace omnitune
