#include "core/OpenCvRadiusBands.h"

#include "core/BallModel.h"
#include "core/Geometry.h"
#include "core/OpenCvHough.h"
#include "core/Pi.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

constexpr int kDirections = 16;  // sampled image angles, for a per-direction ball model

struct RadiusRange {
    double lo = 0;
    double hi = 0;
};

RadiusRange radiusRangeAt(const BallModel& ball, double d)
{
    RadiusRange r{ball.radiusAt(d), ball.radiusAt(d)};
    if (ball.options().directionCos == 0.0 && ball.options().directionSin == 0.0) return r;
    for (int k = 0; k < kDirections; ++k) {
        const double v = ball.radiusAt(d, 2.0 * kPi * k / kDirections);
        r.lo = std::min(r.lo, v);
        r.hi = std::max(r.hi, v);
    }
    return r;
}

OpenCvRadiusBand makeBand(const Geometry& geometry, const OpenCvHoughOptions& o, double d0, double d1, RadiusRange r)
{
    OpenCvRadiusBand b;
    b.minDistancePx = d0;
    b.maxDistancePx = d1;
    b.minRadius = std::max(o.minRadius, int(std::floor(r.lo * o.minRadiusRatio)));
    b.maxRadius = std::max(b.minRadius + 1, std::min(o.maxRadius, int(std::ceil(r.hi * o.maxRadiusRatio))));
    b.accThreshold = std::max(o.bandAccThreshold, o.bandVotesPerPx * 2.0 * kPi * r.lo);
    b.minDist = std::max(1.0, o.bandMinDistRatio * r.lo);
    // Edges up to the largest circle beyond the ring vote for its centres.
    const GeometryOptions& g = geometry.options();
    const double reach = d1 + b.maxRadius + 2.0;
    const cv::Rect box(int(std::floor(g.centerX - reach)), int(std::floor(g.centerY - reach)), int(2 * reach + 1),
                       int(2 * reach + 1));
    b.roi = box & cv::Rect(cv::Point(0, 0), geometry.imageSize());
    return b;
}

}  // namespace

void openCvRadiusBands(const Geometry& geometry, const BallModel& ball, const OpenCvHoughOptions& options,
                       std::vector<OpenCvRadiusBand>& bands)
{
    bands.clear();
    if (options.bandRadiusSpan <= 1.0) return;
    const double inner = geometry.options().innerRadius;
    const double outer = geometry.options().outerRadius;
    // Grow each ring 1 px at a time while its largest expected radius stays within
    // bandRadiusSpan of its smallest.
    double d0 = inner;
    RadiusRange range = radiusRangeAt(ball, d0);
    for (double d = inner + 1.0; d <= outer; d += 1.0) {
        const RadiusRange r = radiusRangeAt(ball, d);
        const RadiusRange grown{std::min(range.lo, r.lo), std::max(range.hi, r.hi)};
        if (grown.hi > grown.lo * options.bandRadiusSpan) {
            bands.push_back(makeBand(geometry, options, d0, d, range));
            d0 = d;
            range = r;
        } else {
            range = grown;
        }
    }
    bands.push_back(makeBand(geometry, options, d0, outer + 1.0, range));
}

}  // namespace omnitune
