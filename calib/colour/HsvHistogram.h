#pragma once
// Histograms of a frame's processed pixels for the colour views: an H-S plane (how many pixels
// have each hue and saturation) and a V histogram.
#include <opencv2/core.hpp>

#include <array>

namespace omnitune {

struct HsvHistogram {
    cv::Mat hs;                // CV_32SC1, 180 rows (H 0..179) x 256 columns (S 0..255): pixel counts
    std::array<int, 256> v{};  // pixel count per V
    int pixels = 0;            // processed pixels counted
};

// `hsv`: the frame in OpenCV HSV; `used`: CV_8UC1, non-zero = processed (empty: every pixel).
HsvHistogram hsvHistogram(const cv::Mat& hsv, const cv::Mat& used);

// The H-S plane as a picture (BGR, 180 columns for H, 256 rows for S with S 255 on top): each
// cell in its own hue and saturation, as bright as the log of its pixel count (black: none).
cv::Mat hsPlaneImage(const HsvHistogram& histogram);

}  // namespace omnitune
