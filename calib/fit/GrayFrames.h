#pragma once
// The frames a geometry fit looks at, as one-channel float images of one size. Takes BGR
// (CV_8UC3), grey (CV_8UC1) and UYVY (CV_8UC2) frames, as the sources deliver them.
#include "calib/fit/FitError.h"

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace omnitune {

// Fills `gray` (CV_32FC1, one per frame) or says which frame is empty, of another size than the
// first, or of a type no source delivers.
std::optional<FitError> toGrayFrames(const std::vector<cv::Mat>& frames, std::vector<cv::Mat>& gray);

}  // namespace omnitune
