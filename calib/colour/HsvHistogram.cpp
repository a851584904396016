#include "calib/colour/HsvHistogram.h"

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

}  // namespace omnitune
