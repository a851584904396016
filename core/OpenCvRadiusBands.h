#pragma once
// Distance rings of the processed area in which the ball's expected radius varies by at most a
// given ratio, each with the cv::HoughCircles parameters that follow from its radius range.
//
// Why: one cv::HoughCircles over the whole radius range ranks a far ball's 4 px circle below
// every larger clutter circle (rim speckle, robot edges) and gives each centre the radius of the
// strongest ring around it; min_dist merges the small ball with a neighbour. Per ring, the
// radius range is the ball's own there, the accumulator threshold scales with its circumference
// and min_dist with its radius.
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

class BallModel;
class Geometry;
struct OpenCvHoughOptions;

struct OpenCvRadiusBand {
    double minDistancePx = 0;  // the ring: centres at [minDistancePx, maxDistancePx) from the mirror centre
    double maxDistancePx = 0;
    int minRadius = 1;         // cv::HoughCircles' radius range, px
    int maxRadius = 1;
    double accThreshold = 1;   // votes
    double minDist = 1;        // px
    cv::Rect roi;              // the image part whose edges can vote for a centre in the ring
};

// Fills `bands` (reusing its storage), inner ring first; empty when options.bandRadiusSpan is
// 0 (one search over min_radius..max_radius, thesis).
void openCvRadiusBands(const Geometry& geometry, const BallModel& ball, const OpenCvHoughOptions& options,
                       std::vector<OpenCvRadiusBand>& bands);

}  // namespace omnitune
