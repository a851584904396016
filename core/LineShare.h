#pragma once
// How much of a candidate's inside is field-line colour. A junction of lines (or a line's end)
// that passes as a far ball is a blob of the line class; a ball shows its panels' colours and
// its shaded side, and only a white ball touching a line is both line-coloured and armed.
#include "core/ColourClasses.h"
#include "core/PaleLine.h"

#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

// Shares of the processed pixels within a disc, %; 0 when none is processed (unusedPct then 100).
struct DiscShares {
    double linePct = 0.0;   // classes with the line role
    double panelPct = 0.0;  // classes with the black, ball or marker role: what a ball's panels show
                            // and a line does not
    double unusedPct = 0.0;  // of all the disc's pixels (in the image or not): masked or outside the mirror
};
// With `pale`, a pale line pixel (core/PaleLine.h) counts as line. No allocation.
DiscShares discShares(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                      double radiusPx, const PaleLine& pale = {});

// discShares(...).linePct. No allocation.
double lineSharePct(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                    double radiusPx);

}  // namespace omnitune
