#pragma once
// Field lines leaving a candidate like spokes. Where two lines meet (a corner, a V where the
// far lines converge at the horizon, a line's end against the rim) the junction is a round
// blob of line colour of a far ball's size, and it passes the shape tests: its edges are round
// and the run-on test's share of rays stays low because the lines are thin (a 2 px line is one
// or two rays of thirty). A ball has no line running straight out of it, except the one line it
// lies on, which leaves on opposite sides. validation.line_arms rejects a candidate with two
// arms at an angle (or three or more).
#include "core/ColourClasses.h"
#include "core/PaleLine.h"

#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

struct LineArms {
    int count = 0;                  // separate arms (groups of neighbouring arm rays)
    double minSeparationDeg = 360;  // smallest angle between two arms' directions
    // A junction: three arms or more, or two whose directions are less than `maxAngleDeg` apart.
    bool junction(double maxAngleDeg) const { return count >= 3 || (count == 2 && minSeparationDeg < maxAngleDeg); }
};

// The arms of the circle at (x, y) of `radiusPx`: a ray is an arm when every step from radiusPx
// out to reach x radiusPx meets a processed line-class pixel on the ray or within lateralPx
// beside it (lines bend and the centre is a pixel off). Masked or out-of-image pixels end an arm.
// A circle whose every ray is an arm lies inside a large line-coloured area: no arms. With
// `pale`, a pale line pixel (core/PaleLine.h) counts as line too. No allocation.
LineArms lineArmsAround(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                        double radiusPx, double reach, double lateralPx, const PaleLine& pale = {});

}  // namespace omnitune
