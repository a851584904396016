#include "core/BallModel.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

double BallModel::radiusAt(double d) const
{
    const double r = options_.c0 + options_.c1 * d + options_.c2 * d * d;
    return std::clamp(r, options_.minRadius, options_.maxRadius);
}

double BallModel::radiusAt(double d, double angleRad) const
{
    if (options_.directionCos == 0.0 && options_.directionSin == 0.0) return radiusAt(d);
    const double r = (options_.c0 + options_.c1 * d + options_.c2 * d * d) *
                     (1.0 + options_.directionCos * std::cos(angleRad) + options_.directionSin * std::sin(angleRad));
    return std::clamp(r, options_.minRadius, options_.maxRadius);
}

double BallModel::squashAt(double d) const
{
    const double k = options_.squashC0 + options_.squashC1 * d + options_.squashC2 * d * d;
    return k > 0.0 ? k : 1.0;
}

namespace {

// Odd so that it is centred on the candidate pixel; an even side rounds down, because one
// pixel too many puts carpet corners into a small ball's square (a 3.7 px ball: 7 px is 0.95
// of its diameter and fails the non-green test).
int squareSide(double radius, double squareRatio)
{
    int side = int(std::lround(2.0 * radius * squareRatio));
    if (side % 2 == 0) --side;
    return std::max(3, side);
}

}  // namespace

int BallModel::squareSizeAt(double distancePx) const
{
    return squareSide(radiusAt(distancePx), options_.squareRatio);
}

int BallModel::squareSizeAt(double distancePx, double angleRad) const
{
    return squareSide(radiusAt(distancePx, angleRad), options_.squareRatio);
}

}  // namespace omnitune
