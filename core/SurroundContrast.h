#pragma once
// A candidate at the mirror's rim stands on the hall's floor edge (issue 9). In dim, noisy light
// the floor between the carpet and the rim is speckled with pixels the LUT calls green, so a
// patch of it shows edges on every side and passes the rim test's shape. What no floor patch
// shows is a colour of its own: its inside has the floor's colour, a ball's has the ball's.
// This measures that step against the surroundings that are not carpet (the floor, a robot, the
// dark beyond the rim), which the carpet around a ball on the field would only dilute.
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

#include <optional>

namespace omnitune {

class FrameColour;

// The colour step (|dB| + |dG| + |dR| of the mean colours, 0-765 levels) between the disc of
// kSurroundInside x `radius` around (x, y) and the processed pixels of no field class in the
// ring from kSurroundFrom x radius + 1 px to kSurroundTo x radius + 1.5 px. None when the disc
// has no processed pixel, or fewer than kSurroundMinShare of the ring's processed pixels are off
// the carpet (a ball in the open: nothing to compare with). `classes` and `used` are CV_8UC1 of
// the frame's size.
std::optional<double> surroundContrast(const FrameColour& colour, const cv::Mat& classes, const cv::Mat& used,
                                       const ColourRoles& roles, int x, int y, double radius);

}  // namespace omnitune
