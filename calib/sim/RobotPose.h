#pragma once
// Where the robot stands on the field, and the change between field and robot coordinates.
//
// Field frame: metres, origin at the centre spot, x along the 18 m length, y across, angles
// counter-clockwise from +x seen from above. Robot frame: metres from the robot centre, +y is
// the robot's forward direction (its heading), +x its right. The omnidirectional image shows
// the robot frame as a map seen from above, not mirrored: robot +x is image +x, robot +y is
// image -y ("up"). So the pipeline's BallDetection xM/yM are robot-frame coordinates, and a
// field direction at angle a appears in the image at angle a - heading + 90 degrees
// (counter-clockwise from image +x with y up).
#include <opencv2/core.hpp>

#include <cmath>

namespace omnitune {

struct RobotPose {
    double x = 0.0;        // m, field frame
    double y = 0.0;        // m
    double heading = 0.0;  // rad, field angle of the robot's forward direction
};

// Field point -> robot frame.
inline cv::Point2d toRobotFrame(const RobotPose& pose, const cv::Point2d& field)
{
    const double dx = field.x - pose.x;
    const double dy = field.y - pose.y;
    const double c = std::cos(pose.heading);
    const double s = std::sin(pose.heading);
    // right = (sin, -cos), forward = (cos, sin)
    return {dx * s - dy * c, dx * c + dy * s};
}

// Robot frame point -> field.
inline cv::Point2d toFieldFrame(const RobotPose& pose, const cv::Point2d& robot)
{
    const double c = std::cos(pose.heading);
    const double s = std::sin(pose.heading);
    return {pose.x + robot.x * s + robot.y * c, pose.y - robot.x * c + robot.y * s};
}

}  // namespace omnitune
