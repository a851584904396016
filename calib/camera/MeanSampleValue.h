#pragma once
// The mean sample value (MSV) of an intensity histogram, ref. [31] of the thesis: the grey levels
// 0..255 are cut into `regions` of equal width, x_j counts the pixels in region j, and
//     MSV = sum_j (j + 1) * x_j / sum_j x_j,     1 <= MSV <= regions.
// A dark image gives ~1, a saturated one ~regions; the middle is a balanced exposure.
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

// Pixels counted per region; `grey` is CV_8UC1, `mask` empty or CV_8UC1 of its size (non-zero = count).
std::vector<double> regionHistogram(const cv::Mat& grey, const cv::Mat& mask, int regions);
// The MSV of such a histogram; 0 when it counts nothing.
double meanSampleValue(const std::vector<double>& histogram);

}  // namespace omnitune
