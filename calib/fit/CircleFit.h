#pragma once
// Robust circle through 2-D points: an algebraic least-squares fit (Kasa), then rounds that drop
// points farther from the circle than a few robust standard deviations and refit, then a
// Gauss-Newton refinement of the geometric distance on the points kept (the algebraic fit is
// biased on a partial arc, which is what a mirror cut by the frame border leaves).
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

struct CircleFitOptions {
    int rounds = 10;             // outlier-rejection rounds at most (stops early when nothing changes)
    double outlierSigma = 3.0;   // a point farther than this many robust sigmas (1.4826 MAD) is dropped
    double minToleranceP = 0.75; // px; a point this close to the circle is always kept (noise-free data has MAD 0)
};

struct CircleFit {
    bool ok = false;             // false when fewer than 3 usable points or they are collinear
    cv::Point2d centre;
    double radius = 0.0;
    std::vector<bool> inlier;    // per input point: kept by the last round
    int inliers = 0;
    double rms = 0.0;            // geometric residual RMS over the inliers, same unit as the points
};

CircleFit fitCircle(const std::vector<cv::Point2d>& points, const CircleFitOptions& options = {});

}  // namespace omnitune
