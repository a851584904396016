#include "calib/colour/HsvImage.h"

#include "core/ColorLut.h"

#include <opencv2/imgproc.hpp>

namespace omnitune {

cv::Mat hsvImage(const cv::Mat& frame, PixelFormat format)
{
    CV_Assert(frame.type() == (format == PixelFormat::Bgr8 ? CV_8UC3 : CV_8UC2));
    cv::Mat bgr = frame;
    // UYVY goes through the same YUV -> BGR conversion as the LUT's YUV table, so both agree.
    if (format == PixelFormat::Uyvy) convertUyvyToBgr(frame, bgr);
    cv::Mat hsv;
    cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
    return hsv;
}

}  // namespace omnitune
