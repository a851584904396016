#pragma once
// The ball the model expects at an image point: its radius at the point's distance from the
// mirror centre and, for an off-axis mirror (ball.direction_cos / _sin), in its direction.
// Every candidate's expected radius comes from here, so the per-direction term reaches the Hough
// maxima, the blob seeds and the OpenCV circles alike; the validation square takes the same
// direction through imageAngleAt at the candidate's own distance (an OpenCV circle may lie off
// the image), and the specific Hough's voting loci have direction sectors of their own.

#include "core/BallCandidate.h"

namespace omnitune {

class BallModel;
class Geometry;

// Image angle of (x, y) about the mirror centre: atan2(dy, dx), x right, y down.
double imageAngleAt(const Geometry& geometry, double x, double y);
// Expected radius (px) of a ball centred at (x, y); exactly ball.radiusAt(distance) without
// a direction term (no angle is computed then).
double expectedRadiusAt(const Geometry& geometry, const BallModel& ball, int x, int y);
// `c` moved to (x, y) for a second look (`how`, and where the search had put it): its distance and
// expected radius there (and the circle's radius, but for an OpenCV circle's), not yet judged
// (rejected None). The rest stays the candidate's.
BallCandidate movedCandidate(const BallCandidate& c, int x, int y, CandidateMove how, const Geometry& geometry,
                             const BallModel& ball);

}  // namespace omnitune
