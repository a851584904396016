#include "core/OpenCvHough.h"

#include "core/BallModel.h"
#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace omnitune {

namespace {

// The centroid of the non-green (binary 0) processed pixels within `radius` of (x, y); the
// point itself when there are none.
cv::Point nonGreenCentroid(const cv::Mat& binary, const Geometry& geometry, cv::Point p, double radius)
{
    const int r = int(std::ceil(radius));
    long sx = 0, sy = 0, n = 0;
    for (int y = std::max(0, p.y - r); y <= std::min(binary.rows - 1, p.y + r); ++y) {
        const std::uint8_t* b = binary.ptr<std::uint8_t>(y);
        for (int x = std::max(0, p.x - r); x <= std::min(binary.cols - 1, p.x + r); ++x) {
            if (b[x] != 0 || (x - p.x) * (x - p.x) + (y - p.y) * (y - p.y) > radius * radius) continue;
            sx += x;
            sy += y;
            ++n;
        }
    }
    if (n == 0) return p;
    const cv::Point c(int(std::lround(double(sx) / n)), int(std::lround(double(sy) / n)));
    return geometry.isUsed(c.x, c.y) ? c : p;
}

}  // namespace

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
        if (cand.rejected == RejectReason::None && options.refineCentre) {
            cv::Point p(cand.x, cand.y);
            for (int it = 0; it < 2; ++it) p = nonGreenCentroid(binary, geometry, p, cand.expectedRadiusPx);
            cand.x = p.x;
            cand.y = p.y;
            cand.distancePx = geometry.distanceAt(p.x, p.y);
            cand.expectedRadiusPx = ball.radiusAt(cand.distancePx);
        }
        if (cand.rejected == RejectReason::None || !options.skipImplausible)
            ++counted;
        else if (implausible++ >= options.maxCircles)
            continue;  // reported up to maxCircles of them: enough to see why
        candidates.push_back(cand);
    }
}

}  // namespace omnitune
