#pragma once
// A candidate at the mirror rim (issue 9): its circle reaches past the outer radius, so the
// circularity sees only its inner part, which the cut-off ends of field lines and robot markers
// pass as well as a far ball does. What tells them apart is the inward side. A ball lies on the
// carpet: walking inwards (towards the mirror centre) from its centre, carpet starts at its
// border. A marker sits on a robot's dark body, a line end runs on inwards as line: their
// inward rays meet something else, or carpet too early or too late.
#include "core/BallEllipse.h"
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

// The inward rays of one candidate: those within the half-angle whose cosine is minInwardCos of
// the direction towards the mirror centre. A ray is judged when it stays on processed pixels;
// it is closed when the first field pixel it meets lies within bandPx of the ball's border
// (skipInnerField: the first one from bandPx inside the border on; the field pixels before it
// are a green panel or carpet noise inside the ball):
// the ellipse of the circle's area squashed radially by `squash` (radial over tangential
// semi-axis, BallModel::squashAt; 1: the circle). Far balls at the rim of a spherical mirror are
// squashed to ~0.6, which a robot's upright marker is not.
struct RimClosure {
    int judged = 0;
    int closed = 0;
    // % of the judged rays that are closed; 0 without judged rays.
    double closedPct() const { return judged > 0 ? 100.0 * closed / judged : 0.0; }
};

RimClosure rimClosure(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                      double radius, double squash, double bandPx, double minInwardCos, bool skipInnerField = false);

// How far (px, both ways added) the candidate's non-field pixels run on along the arc of its own
// distance from the mirror centre, through its centre: about the ball's width for a ball, but a
// line along the rim, or a robot's row of markers and its dark body, runs on. Each way stops at
// the first unprocessed pixel, at the first field pixel after which the arc stays field for
// carpetPx more (0: at the first field pixel; 1 lets a speck of carpet noise in a dim floor not
// end the run), or after maxEachWayPx. `maskedMirrors`: a way that stops at a masked pixel inside
// the ring (a support rod) runs at least as far as the other way, which did not: the ball's far
// side behind the rod is unknown, not narrow.
double rimArcRunPx(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, double x, double y,
                   double maxEachWayPx, double carpetPx = 0.0, bool maskedMirrors = false);

// The widest of those runs along the arcs through the points up to `offsetPx` (whole px steps)
// radially in and out of (x, y): a candidate's centre lies a px or two off the ball's (a Hough
// cell, a blurred border), and the arc through it then crosses the squashed ball off its widest
// chord. 0: the arc through (x, y) alone.
double rimWidestArcRunPx(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                         double maxEachWayPx, double carpetPx, double offsetPx, bool maskedMirrors = false);

// The ball's width (px) along its arc: the tangential axis of the ellipse of the circle's area
// squashed radially by `squash` (1: the circle's diameter).
inline double rimExpectedWidthPx(double radius, double squash)
{
    return 2.0 * squashedTangentialRadius(radius, squash > 0.0 ? squash : 1.0);
}

// How far (px) the circle of `radius` at `distancePx` from the mirror centre reaches past
// outerRadius - marginPx (negative: it ends inside).
inline double rimOverhangPx(double distancePx, double radius, double outerRadius, double marginPx)
{
    return distancePx + radius - (outerRadius - marginPx);
}

}  // namespace omnitune
