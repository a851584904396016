#include "core/BlobSeeds.h"

#include "core/BallModel.h"
#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace omnitune {

const std::vector<BlobSeed>& BlobSeeds::find(const cv::Mat& binary, const Geometry& geometry, const BallModel& ball,
                                             int maxSeeds)
{
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == geometry.imageSize());
    seeds_.clear();
    cv::bitwise_not(binary, nonGreen_);  // 255 = non-green and processed
    const int n = cv::connectedComponentsWithStats(nonGreen_, labels_, stats_, centroids_, 8, CV_32S);
    for (int i = 1; i < n; ++i) {
        const int* st = stats_.ptr<int>(i);
        const int area = st[cv::CC_STAT_AREA];
        if (area < 4) continue;  // pixel speckle, never a ball we could validate
        const int x = int(std::lround(centroids_.at<double>(i, 0)));
        const int y = int(std::lround(centroids_.at<double>(i, 1)));
        if (x < 0 || y < 0 || x >= binary.cols || y >= binary.rows || !geometry.isUsed(x, y)) continue;
        const double r = ball.radiusAt(geometry.distanceAt(x, y));
        const double ratio = area / (M_PI * r * r);
        if (ratio < kMinAreaRatio || ratio > kMaxAreaRatio) continue;
        // Compact: no side longer than the ball (plus a pixel of blur either side).
        const double side = 2.0 * r + 2.0;
        if (st[cv::CC_STAT_WIDTH] > side || st[cv::CC_STAT_HEIGHT] > side) continue;
        seeds_.push_back(BlobSeed{x, y, std::abs(std::log(ratio))});
    }
    std::stable_sort(seeds_.begin(), seeds_.end(), [](const BlobSeed& a, const BlobSeed& b) { return a.fit < b.fit; });
    if (int(seeds_.size()) > maxSeeds) seeds_.resize(std::size_t(std::max(0, maxSeeds)));
    return seeds_;
}

}  // namespace omnitune
