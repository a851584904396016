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
    int counted = 0;  // circles that use up maxCircles
    int implausible = 0;
    for (const cv::Vec3f& c : circles_) {
        if (counted >= options.maxCircles) break;
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
        else if (cand.radiusPx > cand.expectedRadiusPx * options.maxRadiusRatio ||
                 cand.radiusPx < cand.expectedRadiusPx * options.minRadiusRatio)
            cand.rejected = RejectReason::RadiusTooLarge;
        if (cand.rejected == RejectReason::None || !options.skipImplausible)
            ++counted;
        else if (implausible++ >= options.maxCircles)
            continue;  // reported up to maxCircles of them: enough to see why
        candidates.push_back(cand);
    }
}

}  // namespace omnitune
