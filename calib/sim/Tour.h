#pragma once
// The thesis' predefined Tour (ch. 5, Fig. 5.1): the ball lies still at a measured spot and the
// robot drives a closed loop through five waypoints around it (1 -> 2 -> 3 -> 4 -> 5 -> 1),
// so the ball is seen at many distances and image angles. Frames are evenly spaced along the
// loop and fully deterministic for a seed.
#include "calib/sim/SceneSimulator.h"

#include <opencv2/core.hpp>

#include <array>
#include <vector>

namespace omnitune {

struct TourOptions {
    int frames = 300;                  // evenly spaced along the loop (frame 0 at waypoint 1), >= 1
    BallKind ball = BallKind::Orange;
    // m, field frame. The thesis' real positions are near (-0.05, 2.0), which on this field
    // lies on the centre circle: a ball touching a line merges with it and is a harder case
    // (docs/evaluation.md reports it separately). The default keeps the ball on open carpet.
    double ballX = -1.0;
    double ballY = 3.0;                // m
    bool shadow = false;               // the head shadow in every frame
    bool feet = false;                 // a person standing beside the loop in every frame
    bool obstacles = true;             // three robots outside the loop (cyan, magenta, no marker)
    int spinTurns = 1;                 // turns of the ball through the image: the robot faces it at
                                       // waypoint 1 (image up) and turns steadily relative to it
    double lightLevel = 1.0;           // copied into every frame (SceneOptions)
    double lightGradient = 0.0;
    double noiseSigma = 2.0;
    unsigned seed = 1;                 // frame noise, obstacle jitter, distractor spots, ball spin
};

// The five waypoints (field m), 1.1..2.9 m from the ball; along the loop the ball stays
// between ~1.05 and ~2.9 m from the robot centre.
std::array<cv::Point2d, 5> tourWaypoints(const TourOptions& options);

// One SceneOptions per frame. Throws std::invalid_argument when frames < 1.
std::vector<SceneOptions> makeTour(const TourOptions& options);

}  // namespace omnitune
