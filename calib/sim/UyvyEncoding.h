#pragma once
// A rendered BGR frame as an IIDC camera delivers it: YUV 4:2:2 (UYVY), the thesis' own camera
// format and the one the on-robot detector reads from such cameras. The inverse of core's
// yuvToBgr (full-range BT.601); each pixel pair shares the mean of its two U and V values, so a
// frame round-trips with its colour's horizontal detail halved, as a real 4:2:2 camera's does.
#include <opencv2/core.hpp>

namespace omnitune {

// `bgr` CV_8UC3 with an even width; `uyvy` becomes CV_8UC2 of the same size.
void convertBgrToUyvy(const cv::Mat& bgr, cv::Mat& uyvy);

}  // namespace omnitune
