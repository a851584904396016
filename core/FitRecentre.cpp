#include "core/FitRecentre.h"

#include "core/ExpectedRadius.h"
#include "core/Geometry.h"
#include "core/Validation.h"

#include <cmath>

namespace omnitune {

int recentreOnFits(std::vector<BallCandidate>& candidates, std::size_t end, const cv::Mat& classes, const cv::Mat& edges,
                   const Geometry& geometry, const BallModel& ball, const ValidationOptions& options,
                   const FrameColour* colour, const ColourRoles& roles, bool stopAtColour)
{
    if (!options.circleFit || options.refitRecentre <= 0) return 0;
    int tried = 0;
    int kept = 0;
    for (std::size_t i = 0; i < end && i < candidates.size() && tried < options.refitRecentre; ++i) {
        const BallCandidate& c = candidates[i];
        // fitRadiusPx is 0 when no circle was fitted (too few rays): nowhere to move to.
        if (c.rejected != RejectReason::Circularity || !c.scores.shapeMeasured || c.scores.fitRadiusPx <= 0.0) continue;
        const int x = c.x + int(std::lround(c.scores.fitDx));
        const int y = c.y + int(std::lround(c.scores.fitDy));
        if ((x == c.x && y == c.y) || x < 0 || y < 0 || x >= classes.cols || y >= classes.rows || !geometry.isUsed(x, y))
            continue;
        BallCandidate moved = movedCandidate(c, x, y, CandidateMove::ToCircleFit, geometry, ball);
        if (moved.expectedRadiusPx < options.refitMinRadiusPx) continue;
        ++tried;
        validateCandidate(moved, classes, edges, geometry, ball, options, colour, roles, stopAtColour);
        if (moved.rejected != RejectReason::None) continue;
        candidates[i] = moved;
        ++kept;
    }
    return kept;
}

}  // namespace omnitune
