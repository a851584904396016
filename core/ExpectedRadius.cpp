#include "core/ExpectedRadius.h"

#include "core/BallModel.h"
#include "core/Geometry.h"

#include <cmath>

namespace omnitune {

namespace {

bool hasDirectionTerm(const BallModel& ball)
{
    return ball.options().directionCos != 0.0 || ball.options().directionSin != 0.0;
}

}  // namespace

double imageAngleAt(const Geometry& geometry, double x, double y)
{
    return std::atan2(y - geometry.options().centerY, x - geometry.options().centerX);
}

double expectedRadiusAt(const Geometry& geometry, const BallModel& ball, int x, int y)
{
    const double d = geometry.distanceAt(x, y);
    return hasDirectionTerm(ball) ? ball.radiusAt(d, imageAngleAt(geometry, x, y)) : ball.radiusAt(d);
}

BallCandidate movedCandidate(const BallCandidate& c, int x, int y, CandidateMove how, const Geometry& geometry,
                             const BallModel& ball)
{
    BallCandidate moved = c;
    moved.move = how;
    moved.searchX = c.x;
    moved.searchY = c.y;
    moved.x = x;
    moved.y = y;
    moved.distancePx = geometry.distanceAt(x, y);
    moved.expectedRadiusPx = expectedRadiusAt(geometry, ball, x, y);
    // A specific search's circle is the expected one (SpecificHough); an OpenCV circle keeps its own.
    if (c.source != CandidateSource::OpenCvHough) moved.radiusPx = moved.expectedRadiusPx;
    moved.rejected = RejectReason::None;
    return moved;
}

}  // namespace omnitune
