#include "core/RefusalRecentre.h"

#include "core/BallModel.h"
#include "core/CandidatePrefilter.h"
#include "core/CarpetColour.h"
#include "core/DiscCentroid.h"
#include "core/ExpectedRadius.h"
#include "core/FrameColour.h"
#include "core/Geometry.h"
#include "core/RoundHalfAway.h"
#include "core/Validation.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

// The centroid of the processed pixels within `radius` + 1 px of `p` that are not of a field class
// or, where the carpet's colour could be measured, not of that colour; `p` when none.
cv::Point2d centroidOnce(const FrameColour& colour, const cv::Mat& classes, const Geometry& geometry,
                         const ColourRoles& roles, const CarpetColour& carpet, cv::Point2d p, double radius,
                         const ValidationOptions& options)
{
    return discCentroid(classes.size(), p, radius + 1.0, [&](int x, int y) {
        if (!geometry.isUsed(x, y)) return false;
        const bool carpetHere = roles.field(classes.ptr<std::uint8_t>(y)[x]) &&
                                (!carpet.valid() || carpet.matches(colour.hsvAt(x, y), options.carpetTolerance));
        return !carpetHere;
    });
}

}  // namespace

RecentreCounts recentreRefusals(std::vector<BallCandidate>& candidates, std::size_t first, std::size_t end,
                                const cv::Mat& binary,
                                const cv::Mat& classes, const cv::Mat& edges, const Geometry& geometry,
                                const BallModel& ball, const ValidationOptions& options, const FrameColour& colour,
                                const ColourRoles& roles)
{
    const auto processed = [&](cv::Point q) {
        return q.x >= 0 && q.y >= 0 && q.x < classes.cols && q.y < classes.rows && geometry.isUsed(q.x, q.y);
    };
    RecentreCounts n;
    CV_Assert(first <= end && end <= candidates.size());
    for (std::size_t i = first; i < end && n.tried < options.recentreRefused; ++i) {
        const BallCandidate& refused = candidates[i];
        if (refused.rejected != RejectReason::NonGreen || refused.scores.nonGreenPct < options.recentreMinNonGreenPct ||
            refused.expectedRadiusPx < options.recentreMinRadiusPx)
            continue;
        ++n.tried;
        // The carpet is measured once, around the maximum: the ring is wide enough to hold.
        const CarpetColour carpet = options.carpetByColour
                                        ? carpetRingAround(colour, classes, geometry, roles, refused.x, refused.y,
                                                           refused.expectedRadiusPx, options)
                                        : CarpetColour();
        cv::Point2d p(refused.x, refused.y);
        double radius = refused.expectedRadiusPx;
        for (int step = 0; step < 3; ++step) {
            p = centroidOnce(colour, classes, geometry, roles, carpet, p, radius, options);
            const cv::Point q(roundHalfAway(p.x), roundHalfAway(p.y));
            if (!processed(q)) break;
            radius = expectedRadiusAt(geometry, ball, q.x, q.y);
        }
        const cv::Point q(roundHalfAway(p.x), roundHalfAway(p.y));
        if (!processed(q)) continue;
        BallCandidate moved = movedCandidate(refused, q.x, q.y, CandidateMove::ToColourCentroid, geometry, ball);
        // Most moves fail on colour again (dim speckle, a line): their shape is not measured.
        validateCandidate(moved, classes, edges, geometry, ball, options, &colour, roles, true);
        if (moved.rejected != RejectReason::None) continue;
        // Its green must be the ball's: validation's non-green share (panels and greens not the
        // carpet's counted) well above the class share. A white line corner or a line end, which
        // the move centres just as well, has no green of its own.
        const int side = ball.squareSizeAt(moved.distancePx, imageAngleAt(geometry, moved.x, moved.y));
        const SquareShares byClass = classSquareShares(binary, classes, geometry.usedMask(), roles, moved.x, moved.y, side);
        if (moved.scores.nonGreenPct - byClass.nonGreenPct < options.recentreMinPanelPct) continue;
        // The refusal at the front, already passed over, takes this slot.
        const std::size_t front = first + std::size_t(n.kept++);
        candidates[i] = candidates[front];
        candidates[front] = moved;
    }
    return n;
}

}  // namespace omnitune
