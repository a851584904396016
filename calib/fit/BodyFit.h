#pragma once
// The robot's own body in the middle of the mirror image: the inner region that stays the same
// while the field moves. Per pixel the brightness variance over several frames, averaged in
// rings around the mirror centre; the body's rings vary only by sensor noise, the field's by
// what passes over them. The inner radius is proposed a margin outside the radius where the
// variance rises.
#include "calib/fit/FitError.h"
#include "core/Progress.h"

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace omnitune {

struct BodyFitOptions {
    int minFrames = 3;           // frames the variance needs; more, with the robot turning or driving, is better
    double rise = 0.5;           // the body ends where the ring variance reaches this share of the way from
                                 // the body's level to the field's (0..1)
    double minFieldRatio = 4.0;  // the field's ring variance must be this many times the body's, or the field
                                 // did not move
    double marginPx = 2.0;       // px; inner radius proposed this far outside the body's edge
};

struct BodyFit {
    double bodyRadius = 0.0;           // px, where the ring variance rises
    double innerRadius = 0.0;          // px, proposed geometry.inner_radius: bodyRadius + marginPx
    double bodyLevel = 0.0;            // grey level^2, ring variance inside the body (sensor noise)
    double fieldLevel = 0.0;           // grey level^2, typical ring variance over the field
    std::vector<double> ringVariance;  // per whole px of radius from the centre, up to the rim (for a plot)
    int frames = 0;
};

struct BodyFitResult {
    BodyFit fit;  // meaningful only when ok()
    std::optional<FitError> error;

    bool ok() const { return !error.has_value(); }
};

// `centre` and `rimRadius` from the rim fit (or the config). `progress` may be null.
BodyFitResult fitBody(const std::vector<cv::Mat>& frames, cv::Point2d centre, double rimRadius,
                      const BodyFitOptions& options = {}, Progress* progress = nullptr);

}  // namespace omnitune
