#pragma once
// Where on the ground a ball seen at an image point lies, relative to the robot: the
// pipeline's final step (thesis ch. 4.3), shared with ground-truth marking in the workbench
// so a hand-marked ball and a detected one are measured the same way.
#include "core/DistanceMap.h"

namespace omnitune {

struct BallPosition {
    double distancePx = 0.0;  // image distance from the robot centre
    double distanceM = 0.0;   // horizontal, ball-height corrected
    double xM = 0.0;          // m, the robot's right (image +x)
    double yM = 0.0;          // m, the robot's forward (image -y)
};

BallPosition ballPositionAt(double px, double py, double centreX, double centreY, const DistanceMap& map);

}  // namespace omnitune
