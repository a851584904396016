#pragma once
// What the panes draw over the images, and which of it is switched on.
#include "BallCandidate.h"
#include "Config.h"
#include "PipelineResult.h"

#include <vector>

namespace omnitune {

struct OverlayOptions {
    bool geometry = true;      // robot centre, inner and outer radius, mask outline
    bool areas = true;         // the radial areas of the specific Hough
    bool sensors = false;      // radial sensor rays
    bool candidates = true;    // every candidate with its three scores
    bool ball = true;          // the accepted ball with its world position
    bool cursorRadius = true;  // the expected ball circle under the cursor
};

struct OverlayData {
    Config config;                        // geometry, areas, ball model, sensors of the run
    std::vector<BallCandidate> candidates;
    BallDetection detection;
};

}  // namespace omnitune
