#include "calib/mask/MaskOutline.h"

#include <opencv2/imgproc.hpp>

namespace omnitune {

Polylines maskOutline(const cv::Mat& mask)
{
    Polylines lines;
    if (mask.empty() || mask.type() != CV_8UC1) return lines;
    cv::Mat processed = mask != 0;  // findContours wants a 0/non-zero image it may keep
    cv::findContours(processed, lines, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
    return lines;
}

}  // namespace omnitune
