#pragma once
// A whole frame in OpenCV's 8-bit HSV (H 0..179, S and V 0..255), from either pixel format: what
// the histograms, the class shares and the magic wand read. The LUT never needs it.
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

namespace omnitune {

// `frame`: CV_8UC3 for Bgr8, CV_8UC2 for Uyvy. Returns CV_8UC3 HSV of the same size.
cv::Mat hsvImage(const cv::Mat& frame, PixelFormat format);

}  // namespace omnitune
