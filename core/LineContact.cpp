#include "core/LineContact.h"

#include "core/Geometry.h"
#include "core/RoundHalfAway.h"

#include <cmath>

namespace omnitune {

LineContactRay::LineContactRay(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                               double ca, double sa, double minEntryPx, double reachPx)
    : classes_(classes), geometry_(geometry), roles_(roles), x_(x), y_(y), ca_(ca), sa_(sa), minEntryPx_(minEntryPx),
      reachPx_(reachPx)
{
}

bool LineContactRay::entersLine(cv::Point p, double r)
{
    if (!ownSoFar_) return false;
    const std::uint8_t cls = classes_.ptr<std::uint8_t>(p.y)[p.x];
    if (roles_.field(cls)) ownSoFar_ = false;
    if (!roles_.line(cls)) return false;
    ownSoFar_ = false;
    return r >= minEntryPx_ - 1e-9 && lineGoesOn(r);
}

bool LineContactRay::lineGoesOn(double fromR) const
{
    for (double r = fromR; r <= reachPx_ + 1e-9; r += 0.5) {
        const int px = roundHalfAway(x_ + r * ca_);
        const int py = roundHalfAway(y_ + r * sa_);
        if (px < 0 || py < 0 || px >= classes_.cols || py >= classes_.rows) return true;
        if (!geometry_.isUsed(px, py)) continue;  // a rod across the line: unknown, not its end
        if (!roles_.line(classes_.ptr<std::uint8_t>(py)[px])) return false;
    }
    return true;
}

}  // namespace omnitune
