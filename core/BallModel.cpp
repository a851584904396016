#include "BallModel.h"

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
    const int side = int(std::lround(2.0 * radiusAt(distancePx) * options_.squareRatio));
    return std::max(3, side | 1);  // odd, so the square is centred on the candidate pixel
}

}  // namespace omnitune
