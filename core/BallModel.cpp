#include "BallModel.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

BallModel::BallModel(const BallModelOptions& options, int maxDistance) : options_(options)
{
    radiusTable_.resize(std::size_t(std::max(maxDistance, 0) + 1));
    for (std::size_t d = 0; d < radiusTable_.size(); ++d) {
        radiusTable_[d] = int(std::lround(radiusAt(double(d))));
        maxRadiusPx_ = std::max(maxRadiusPx_, radiusTable_[d]);
    }
}

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
