#pragma once
// What one frame of the optics simulator shows: the robot's pose, the ball as a 3D sphere, the
// things around it, the carpet and the light. Pure data; OpticsRenderer draws it.
#include "calib/sim/BallKind.h"
#include "calib/sim/RobotPose.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

// Another robot: a black cylinder with a coloured marker band.
struct OpticsRobot {
    cv::Point2d at;        // m, field frame
    double radius = 0.25;  // m
    double height = 0.7;   // m
    int team = 1;          // 0 no band, 1 cyan, 2 magenta
};

struct OpticsScene {
    RobotPose robot;
    bool ballPresent = true;
    cv::Point2d ball{0.0, 2.0};  // m, field frame, ball centre over the floor
    double ballRadius = 0.11;    // m
    BallKind ballKind = BallKind::Orange;
    double ballSpin = 0.0;       // rad, turns the panels
    std::vector<OpticsRobot> robots;
    bool feet = false;
    cv::Point2d feetAt;          // m, field frame, between the shoes
    bool headShadow = false;
    cv::Point2d headShadowAt;    // m, robot frame, centre of the shadow on the floor

    cv::Vec3f carpet{40, 140, 40};  // BGR at normal light
    double light = 1.0;          // overall level: dim ~0.35, bright ~1.6 (clips)
    bool uneven = false;         // vignetting towards the rim plus a bright hall side and a spotlight
    double noiseSigma = 1.5;     // Gaussian sensor noise per channel, grey levels
    double opticalBlurPx = 0.6;  // Gaussian sigma over the frame, px
    double motionBlurPx = 0.0;   // length of the ball's smear in the image, px
    double motionAngle = 0.0;    // rad, image direction of that smear (from +x, y down)
    unsigned seed = 1;           // sensor noise
};

// What the optics say about the ball: its silhouette is every pixel whose reflected ray hits
// the sphere, before anything (rod, robot, body) hides it.
struct OpticsTruth {
    bool ballVisible = false;     // >= half the silhouette unhidden and inside the frame
    double px = 0.0, py = 0.0;    // silhouette centroid, px
    double radiusPx = 0.0;        // sqrt(area / pi)
    double area = 0.0;            // px^2 of the silhouette
    double visibleFraction = 0.0; // unhidden share of the silhouette inside the frame
    double xM = 0.0, yM = 0.0;    // m, robot frame: right, forward
    double distanceM = 0.0;       // m, horizontal, robot centre to ball centre
    cv::Rect box;                 // px, the region the ball was rendered in
    RobotPose pose;
};

}  // namespace omnitune
