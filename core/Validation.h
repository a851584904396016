#pragma once
// Thesis section 4.4: a candidate is a ball only if, in its square, enough pixels are
// non-green and non-black, and enough of its circle is present as edges (circularity).
#include "BallCandidate.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

class Geometry;
class BallModel;

struct ValidationOptions {
    double minNonGreenPct = 85.0;    // %; the ball is never green and fills its square
    double minNonBlackPct = 50.0;    // %; rejects black robots; higher would lose part-black balls
    double minCircularityPct = 70.0; // %; a still ball gives ~90, motion blur lowers it
    double radiusTolerance = 0.15;   // fraction of the expected radius searched for an edge
    double minRadiusBandPx = 1.0;    // px; the search band is never thinner (far, small balls)
};

// Scores one candidate and sets its `rejected` field (first failing test in thesis order:
// non-green, non-black, circularity). `classes` holds colour class ids, `edges` the edge image.
void validateCandidate(BallCandidate& candidate, const cv::Mat& classes, const cv::Mat& edges,
                       const Geometry& geometry, const BallModel& ball, const ValidationOptions& options);

// The three scores alone, for a circle at (x, y) of the given radius and square side.
ValidationScores scoreCircle(int x, int y, double radius, int squareSide, const cv::Mat& classes,
                             const cv::Mat& edges, const Geometry& geometry, const ValidationOptions& options);

}  // namespace omnitune
