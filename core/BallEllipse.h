#pragma once
// The ball as a mirror squashes it (ball.squash_*, BallModel::squashAt): the ellipse of the same
// area as the ball's circle of radius r, its radial over tangential semi-axis `squash`. So its
// tangential semi-axis is r / sqrt(squash) and its radial one r x sqrt(squash). Validation's
// circularity and run-on, the rim test and the blob seeds all measure against this one shape.
#include <cmath>

namespace omnitune {

// How far out (in units of r) the ellipse reaches in a direction whose cosines along the radial
// and the tangential axis are `alongRadial` and `alongTangential`. 1 everywhere for squash 1.
inline double squashedReach(double alongRadial, double alongTangential, double squash)
{
    return 1.0 / std::sqrt(alongRadial * alongRadial / squash + squash * alongTangential * alongTangential);
}

// The ellipse's tangential semi-axis (its longer one for squash < 1), px.
inline double squashedTangentialRadius(double radius, double squash) { return radius / std::sqrt(squash); }

}  // namespace omnitune
