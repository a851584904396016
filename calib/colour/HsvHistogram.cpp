#include "calib/colour/HsvHistogram.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace omnitune {

HsvHistogram hsvHistogram(const cv::Mat& hsv, const cv::Mat& used)
{
    CV_Assert(hsv.type() == CV_8UC3 && (used.empty() || (used.type() == CV_8UC1 && used.size() == hsv.size())));
    HsvHistogram res;
    res.hs = cv::Mat(180, 256, CV_32SC1, cv::Scalar(0));
    for (int y = 0; y < hsv.rows; ++y) {
        const cv::Vec3b* row = hsv.ptr<cv::Vec3b>(y);
        const std::uint8_t* use = used.empty() ? nullptr : used.ptr<std::uint8_t>(y);
        for (int x = 0; x < hsv.cols; ++x) {
            if (use && !use[x]) continue;
            ++res.hs.at<int>(row[x][0], row[x][1]);
            ++res.v[row[x][2]];
            ++res.pixels;
        }
    }
    return res;
}

cv::Mat hsPlaneImage(const HsvHistogram& histogram)
{
    CV_Assert(histogram.hs.type() == CV_32SC1 && histogram.hs.rows == 180 && histogram.hs.cols == 256);
    double top = 0;
    cv::minMaxLoc(histogram.hs, nullptr, &top);
    const double scale = top > 0 ? 255.0 / std::log1p(top) : 0.0;
    cv::Mat hsv(256, 180, CV_8UC3);
    for (int s = 0; s < 256; ++s)
        for (int h = 0; h < 180; ++h) {
            const int n = histogram.hs.at<int>(h, s);
            // A cell with a few pixels still shows (at least 60 of 255): the eye finds the rare colours.
            const int v = n == 0 ? 0 : std::max(60, int(std::lround(std::log1p(double(n)) * scale)));
            hsv.at<cv::Vec3b>(255 - s, h) = cv::Vec3b(std::uint8_t(h), std::uint8_t(s), std::uint8_t(v));
        }
    cv::Mat bgr;
    cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
    return bgr;
}

}  // namespace omnitune
