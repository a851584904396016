#pragma once
// What a team would measure on the simulated robot (calib/fit/CameraMeasurements.h), taken
// from the rendered optics the way a team takes it: marks on the floor every 0.25 m along a few
// directions (every 0.05 m close against the body) located in the image (~0.3 px), the ball laid
// at known distances and its circle located (~0.3 px), empty-field frames while the robot turns,
// the mask painted over rods and body (2 px wider), the viewpoint height as the camera's makers
// state it. Normal light, green carpet: the team measures at home.
#include "calib/fit/CameraMeasurements.h"
#include "calib/sim/optics/OpticsRenderer.h"

namespace omnitune {

struct OpticsMeasurementOptions {
    int markDirections = 6;       // directions of the floor marks
    double firstMarkM = 0.4;      // m, the first of the marks laid every markStepM
    double markStepM = 0.25;      // m between marks, from firstMarkM out to the farthest visible
    // Marks laid close against the body, where the mirror's scale changes fastest (the ball
    // there looks squashed): every nearMarkStepM from nearMarksFromM to the second far mark.
    double nearMarksFromM = 0.3;
    double nearMarkStepM = 0.05;
    double locateNoisePx = 0.3;   // px, how exactly a mark or the ball centre is located
    double radiusNoisePx = 0.25;  // px, how exactly the ball's radius is located
    int ballDirections = 8;
    int emptyFrames = 6;
    int maskDilatePx = 2;
    unsigned seed = 7;
};

CameraMeasurements measureOpticsCamera(const OpticsRenderer& renderer, const OpticsMeasurementOptions& options = {});

}  // namespace omnitune
