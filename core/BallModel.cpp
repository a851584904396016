#include "core/BallModel.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

double BallModel::radiusAt(double d) const
{
    const double r = options_.c0 + options_.c1 * d + options_.c2 * d * d;
    return std::clamp(r, options_.minRadius, options_.maxRadius);
}

int BallModel::squareSizeAt(double distancePx) const
{
    // Odd so that it is centred on the candidate pixel; an even side rounds down, because one
    // pixel too many puts carpet corners into a small ball's square (a 3.7 px ball: 7 px is
    // 0.95 of its diameter and fails the non-green test).
    int side = int(std::lround(2.0 * radiusAt(distancePx) * options_.squareRatio));
    if (side % 2 == 0) --side;
    return std::max(3, side);
}

}  // namespace omnitune
