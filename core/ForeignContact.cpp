#include "core/ForeignContact.h"

#include "core/Geometry.h"
#include "core/RoundHalfAway.h"

#include <array>
#include <cmath>

namespace omnitune {

ForeignContactRay::ForeignContactRay(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles,
                                     ColorClass ballClass, int x, int y, double ca, double sa, double minEntryPx,
                                     double reachPx)
    : classes_(classes), geometry_(geometry), roles_(roles), ball_(std::uint8_t(ballClass)), x_(x), y_(y), ca_(ca),
      sa_(sa), minEntryPx_(minEntryPx), reachPx_(reachPx), ownSoFar_(ballClass != ColorClass::Unknown)
{
}

bool ForeignContactRay::entersObject(cv::Point p, double r)
{
    if (!ownSoFar_) return false;
    const std::uint8_t cls = classes_.ptr<std::uint8_t>(p.y)[p.x];
    if (cls == ball_ || roles_.black(cls)) return false;  // still the ball, or its shaded side
    ownSoFar_ = false;
    // Carpet is the ball's own border; a line is LineContactRay's business.
    if (roles_.field(cls) || roles_.line(cls)) return false;
    return r >= minEntryPx_ - 1e-9 && objectGoesOn(r);
}

bool ForeignContactRay::objectGoesOn(double fromR) const
{
    for (double r = fromR; r <= reachPx_ + 1e-9; r += 0.5) {
        const int px = roundHalfAway(x_ + r * ca_);
        const int py = roundHalfAway(y_ + r * sa_);
        if (px < 0 || py < 0 || px >= classes_.cols || py >= classes_.rows) return true;
        if (!geometry_.isUsed(px, py)) continue;  // a rod across the object: unknown, not its end
        const std::uint8_t cls = classes_.ptr<std::uint8_t>(py)[px];
        // Carpet soon after: the blurred blend at the ball's own border, not an object.
        if (roles_.field(cls) || cls == ball_) return false;
    }
    return true;
}

ColorClass ballClassAt(const cv::Mat& classes, const ColourRoles& roles, int x, int y)
{
    std::array<int, 32> votes{};
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int px = x + dx;
            const int py = y + dy;
            if (px < 0 || py < 0 || px >= classes.cols || py >= classes.rows) continue;
            const std::uint8_t cls = classes.ptr<std::uint8_t>(py)[px];
            if (cls < votes.size() && roles.is(cls, ColourRole::Ball)) ++votes[cls];
        }
    for (std::size_t id = 0; id < votes.size(); ++id)
        if (votes[id] >= 5) return ColorClass(id);
    return ColorClass::Unknown;
}

}  // namespace omnitune
