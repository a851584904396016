#pragma once
// The ball the model expects at an image point: its radius and validation square at the point's
// distance from the mirror centre and, for an off-axis mirror (ball.direction_cos / _sin), in
// its direction. Every candidate's expected radius comes from here, so the per-direction term
// reaches the Hough maxima, the blob seeds, the OpenCV circles and the validation alike.
// The specific Hough's voting loci stay per distance only (a few per cent of radius, inside
// the vote's tolerance).

namespace omnitune {

class BallModel;
class Geometry;

// Image angle of (x, y) about the mirror centre: atan2(dy, dx), x right, y down.
double imageAngleAt(const Geometry& geometry, double x, double y);
// Expected radius (px) of a ball centred at (x, y); exactly ball.radiusAt(distance) without
// a direction term (no angle is computed then).
double expectedRadiusAt(const Geometry& geometry, const BallModel& ball, int x, int y);
// Odd side (px) of the validation square of a ball centred at (x, y).
int expectedSquareAt(const Geometry& geometry, const BallModel& ball, int x, int y);

}  // namespace omnitune
