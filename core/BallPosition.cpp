#include "core/BallPosition.h"

#include <cmath>

namespace omnitune {

BallPosition ballPositionAt(double px, double py, double centreX, double centreY, const DistanceMap& map)
{
    BallPosition b;
    b.distancePx = std::hypot(px - centreX, py - centreY);
    b.distanceM = map.ballDistance(b.distancePx);
    const double angle = std::atan2(-(py - centreY), px - centreX);
    b.xM = b.distanceM * std::cos(angle);
    b.yM = b.distanceM * std::sin(angle);
    return b;
}

}  // namespace omnitune
