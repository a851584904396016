#include "core/OpenCvHough.h"

#include "core/BallModel.h"
#include "core/DiscCentroid.h"
#include "core/Geometry.h"
#include "core/ExpectedRadius.h"
#include "core/RoundHalfAway.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

// The centroid of the non-green (binary 0) pixels within `radius` of p; p itself when there are
// none.
cv::Point2d nonGreenCentroid(const cv::Mat& binary, cv::Point2d p, double radius)
{
    return discCentroid(binary.size(), p, radius, [&](int x, int y) { return binary.ptr<std::uint8_t>(y)[x] == 0; });
}

// Whether a circle centre at (x, y) lies where validation can judge it: a processed pixel, or with
// masked_centres a masked one inside the ring.
bool centreJudged(const Geometry& geometry, const OpenCvHoughOptions& options, int x, int y)
{
    const cv::Size size = geometry.imageSize();
    if (x < 0 || y < 0 || x >= size.width || y >= size.height) return false;
    if (geometry.isUsed(x, y)) return true;
    const cv::Mat& masked = geometry.maskedInRing();
    return options.maskedCentres && !masked.empty() && masked.at<std::uint8_t>(y, x) != 0;
}

}  // namespace

void OpenCvHough::process(const cv::Mat& binary, const OpenCvHoughOptions& options, const Geometry& geometry,
                          const BallModel& ball, std::vector<BallCandidate>& candidates)
{
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == geometry.imageSize());
    // The circles and their refined centres come from the filled image; validation still reads
    // the frame's own classes.
    const cv::Mat& input = maskFill_.apply(binary, geometry, options.maskFillPx);
    openCvRadiusBands(geometry, ball, options, bands_);
    if (bands_.empty()) {
        circles_.clear();
        cv::HoughCircles(input, circles_, cv::HOUGH_GRADIENT, options.dp, options.minDist, options.cannyHigh,
                         options.accThreshold, options.minRadius, options.maxRadius);
        Pass all;
        all.maxCounted = options.maxCircles;
        appendCircles(input, options, geometry, ball, all, candidates);
        return;
    }
    if (rings_.size() != bands_.size()) rings_.resize(bands_.size());
    for (std::size_t i = 0; i < bands_.size(); ++i) {
        const OpenCvRadiusBand& b = bands_[i];
        if (b.roi.empty()) continue;
        circles_.clear();
        cv::HoughCircles(ringInput(input, geometry, i), circles_, cv::HOUGH_GRADIENT, options.bandDp, b.minDist, options.cannyHigh,
                         b.accThreshold, b.minRadius, b.maxRadius);
        Pass pass;
        pass.offset = b.roi.tl();
        pass.minDistancePx = b.minDistancePx;
        pass.maxDistancePx = b.maxDistancePx;
        pass.maxCounted = options.bandCircles;
        appendCircles(input, options, geometry, ball, pass, candidates);
    }
}

const cv::Mat& OpenCvHough::ringInput(const cv::Mat& binary, const Geometry& geometry, std::size_t i)
{
    const OpenCvRadiusBand& b = bands_[i];
    RingImage& ring = rings_[i];
    const GeometryOptions& g = geometry.options();
    const bool same = ring.band.roi == b.roi && ring.band.minDistancePx == b.minDistancePx &&
                      ring.band.maxDistancePx == b.maxDistancePx && ring.band.maxRadius == b.maxRadius &&
                      ring.centreX == g.centerX && ring.centreY == g.centerY && !ring.outside.empty();
    if (!same) {
        ring.band = b;
        ring.centreX = g.centerX;
        ring.centreY = g.centerY;
        const double reach = b.maxRadius + 2.0;
        const cv::Point c(roundHalfAway(g.centerX) - b.roi.x, roundHalfAway(g.centerY) - b.roi.y);
        ring.outside.create(b.roi.size(), CV_8UC1);
        ring.outside.setTo(255);
        cv::circle(ring.outside, c, int(std::ceil(b.maxDistancePx + reach)), 0, cv::FILLED);
        const int innerReach = int(std::floor(b.minDistancePx - reach));
        if (innerReach > 0) cv::circle(ring.outside, c, innerReach, 255, cv::FILLED);
    }
    cv::bitwise_or(binary(b.roi), ring.outside, ring.input);
    return ring.input;
}

void OpenCvHough::appendCircles(const cv::Mat& binary, const OpenCvHoughOptions& options, const Geometry& geometry,
                               const BallModel& ball, const Pass& pass, std::vector<BallCandidate>& candidates)
{
    const GeometryOptions& g = geometry.options();
    // OpenCV returns the circles strongest first.
    int counted = 0;  // circles that use up maxCounted
    int implausible = 0;
    for (cv::Vec3f c : circles_) {
        if (counted >= pass.maxCounted) break;
        c[0] += float(pass.offset.x);
        c[1] += float(pass.offset.y);
        if (pass.maxDistancePx > 0) {
            // Another ring's circle: that ring's own search judges it.
            const double d = std::hypot(c[0] - g.centerX, c[1] - g.centerY);
            if (d < pass.minDistancePx || d >= pass.maxDistancePx) continue;
        }
        BallCandidate cand;
        cand.source = CandidateSource::OpenCvHough;
        cand.x = roundHalfAway(c[0]);
        cand.y = roundHalfAway(c[1]);
        cand.radiusPx = c[2];
        const bool inside = cand.x >= 0 && cand.y >= 0 && cand.x < binary.cols && cand.y < binary.rows;
        cand.distancePx = inside ? geometry.distanceAt(cand.x, cand.y) : 0.0;
        cand.expectedRadiusPx = inside ? expectedRadiusAt(geometry, ball, cand.x, cand.y) : ball.radiusAt(0.0);
        if (!centreJudged(geometry, options, cand.x, cand.y))
            cand.rejected = RejectReason::OutsideArea;
        else if (cand.radiusPx > cand.expectedRadiusPx * options.maxRadiusRatio ||
                 cand.radiusPx < cand.expectedRadiusPx * options.minRadiusRatio)
            cand.rejected = RejectReason::RadiusTooLarge;
        if (cand.rejected == RejectReason::None && options.refineCentre) {
            // Sub-pixel steps; the window reaches a pixel past the ball for its blurred border.
            cv::Point2d p(c[0], c[1]);
            for (int it = 0; it < 3; ++it) p = nonGreenCentroid(binary, p, cand.expectedRadiusPx + 1.0);
            const cv::Point q(roundHalfAway(p.x), roundHalfAway(p.y));
            if (centreJudged(geometry, options, q.x, q.y)) {
                cand.x = q.x;
                cand.y = q.y;
                cand.distancePx = geometry.distanceAt(q.x, q.y);
                cand.expectedRadiusPx = expectedRadiusAt(geometry, ball, q.x, q.y);
            }
        }
        if (cand.rejected == RejectReason::None || !options.skipImplausible)
            ++counted;
        else if (implausible++ >= options.maxCircles)
            continue;  // reported up to maxCircles of them: enough to see why
        candidates.push_back(cand);
    }
}

}  // namespace omnitune
