#pragma once
// The border of a mask image's processed region as polylines (image px), so the workbench can
// draw where the robot body and mirror supports are cut out without covering the frame.
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

using Polylines = std::vector<std::vector<cv::Point>>;

// `mask`: CV_8UC1, non-zero = processed (Config::mask). Empty mask: no lines.
Polylines maskOutline(const cv::Mat& mask);

}  // namespace omnitune
