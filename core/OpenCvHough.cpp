#include "core/OpenCvHough.h"

#include "core/BallModel.h"
#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace omnitune {

void OpenCvHough::process(const cv::Mat& binary, const OpenCvHoughOptions& options, const Geometry& geometry,
                          const BallModel& ball, std::vector<BallCandidate>& candidates)
{
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == geometry.imageSize());
    circles_.clear();
    cv::HoughCircles(binary, circles_, cv::HOUGH_GRADIENT, options.dp, options.minDist, options.cannyHigh,
                     options.accThreshold, options.minRadius, options.maxRadius);
    // OpenCV returns the circles strongest first.
    const int n = std::min<int>(int(circles_.size()), options.maxCircles);
    for (int i = 0; i < n; ++i) {
        const cv::Vec3f& c = circles_[std::size_t(i)];
        BallCandidate cand;
        cand.source = CandidateSource::OpenCvHough;
        cand.x = int(std::lround(c[0]));
        cand.y = int(std::lround(c[1]));
        cand.radiusPx = c[2];
        const bool inside = cand.x >= 0 && cand.y >= 0 && cand.x < binary.cols && cand.y < binary.rows;
        cand.distancePx = inside ? geometry.distanceAt(cand.x, cand.y) : 0.0;
        cand.expectedRadiusPx = ball.radiusAt(cand.distancePx);
        if (!inside || !geometry.isUsed(cand.x, cand.y))
            cand.rejected = RejectReason::OutsideArea;
        else if (cand.radiusPx > cand.expectedRadiusPx * options.maxRadiusRatio)
            cand.rejected = RejectReason::RadiusTooLarge;
        candidates.push_back(cand);
    }
}

}  // namespace omnitune
