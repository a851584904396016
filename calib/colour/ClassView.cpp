#include "calib/colour/ClassView.h"

namespace omnitune {

cv::Mat classView(const cv::Mat& segmented, const cv::Mat& classes, const cv::Mat& overlap, const ClassViewOptions& o)
{
    CV_Assert(segmented.type() == CV_8UC3 && classes.type() == CV_8UC1 && classes.size() == segmented.size());
    CV_Assert(overlap.empty() || (overlap.type() == CV_8UC1 && overlap.size() == segmented.size()));
    cv::Mat out = segmented.clone();
    for (int y = 0; y < out.rows; ++y) {
        cv::Vec3b* row = out.ptr<cv::Vec3b>(y);
        const std::uint8_t* id = classes.ptr<std::uint8_t>(y);
        const std::uint8_t* over = overlap.empty() ? nullptr : overlap.ptr<std::uint8_t>(y);
        for (int x = 0; x < out.cols; ++x) {
            if (o.onlyClass >= 0 && id[x] != o.onlyClass) row[x] = row[x] / 4;  // dim, still recognisable
            // Diagonal stripes 2 px wide: visible at the fitted zoom, unlike a 1 px checkerboard.
            if (o.flagOverlaps && over && over[x])
                row[x] = ((x + y) / 2) % 2 ? cv::Vec3b(255, 255, 255) : cv::Vec3b(0, 0, 255);
        }
    }
    return out;
}

}  // namespace omnitune
