#pragma once
// The ball's radial squash (ball.squash_c0..c2) from the fitted distance map. A sphere is seen
// under a circular cone of directions; the mirror maps a direction's angle from the downward
// axis, alpha, to the image radius rho and keeps its azimuth. So the ball's image is an ellipse
// whose radial over tangential semi-axis is k = (d rho / d alpha) sin(alpha) / rho, with
// tan(alpha) = D(rho) / H from the distance map D and the viewpoint height H: ~1 behind a
// single-viewpoint (hyperbolic) mirror, ~0.6-0.7 near the rim of a spherical one.
#include "core/DistanceMap.h"

#include <array>
#include <optional>

namespace omnitune {

struct BallSquashFitOptions {
    double stepPx = 2.0;        // the ratio is sampled every stepPx over the ring
    double derivativePx = 4.0;  // d alpha / d rho by central differences over +- this (smooths a table's kinks)
};

// c0, c1, c2 of k(d) = c0 + c1*d + c2*d^2 (d in px) fitted over innerRadius..outerRadius; empty
// when the map gives no positive ratio there (fewer than 3 samples).
std::optional<std::array<double, 3>> fitBallSquash(const DistanceMapOptions& map, double innerRadius, double outerRadius,
                                                   const BallSquashFitOptions& options = {});

}  // namespace omnitune
