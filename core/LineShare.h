#pragma once
// How much of a candidate's inside is field-line colour. A junction of lines (or a line's end)
// that passes as a far ball is a blob of the line class; a ball shows its panels' colours and
// its shaded side, and only a white ball touching a line is both line-coloured and armed.
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

// % of the processed pixels within `radiusPx` of (x, y) whose class has the line role; 0 when
// none is processed. No allocation.
double lineSharePct(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                    double radiusPx);

}  // namespace omnitune
