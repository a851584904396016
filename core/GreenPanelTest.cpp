#include "core/GreenPanelTest.h"

#include "core/RoundHalfAway.h"

#include <cmath>

namespace omnitune {

namespace {

// Whether walking from `p` in the unit direction (dx, dy), 0.5 px steps, a known pixel of no
// field class comes before the walk leaves the disc (less `marginPx`) or the known pixels.
bool wallAlong(cv::Point p, double dx, double dy, const BallDisc& disc, double marginPx, const PanelPixels& pixels)
{
    const double end2 = (disc.radius - marginPx) * (disc.radius - marginPx);
    cv::Point last = p;
    for (double r = 0.5;; r += 0.5) {
        const double fx = p.x + r * dx;
        const double fy = p.y + r * dy;
        if ((fx - disc.x) * (fx - disc.x) + (fy - disc.y) * (fy - disc.y) > end2) return false;
        const cv::Point q(roundHalfAway(fx), roundHalfAway(fy));
        if (q == last) continue;
        last = q;
        if (!pixels.known(q)) return false;
        if (!pixels.field(q)) return true;
    }
}

}  // namespace

bool enclosedFrom(cv::Point p, const BallDisc& disc, double marginPx, int minDirections, const PanelPixels& pixels)
{
    constexpr double kDiag = 0.70710678118654752;
    static const double dirs[8][2] = {{1, 0}, {kDiag, kDiag}, {0, 1}, {-kDiag, kDiag}, {-1, 0}, {-kDiag, -kDiag}, {0, -1}, {kDiag, -kDiag}};
    // Stops as soon as the answer is known: enough walls found, or too few directions left.
    int found = 0;
    for (int i = 0; i < 8; ++i) {
        if (found >= minDirections) return true;
        if (found + (8 - i) < minDirections) return false;
        found += wallAlong(p, dirs[i][0], dirs[i][1], disc, marginPx, pixels);
    }
    return found >= minDirections;
}

bool onEnclosedPanel(cv::Point p, const BallDisc& disc, double marginPx, const PanelPixels& pixels)
{
    double dx = p.x - disc.x;
    double dy = p.y - disc.y;
    const double d = std::hypot(dx, dy);
    const double end = disc.radius - marginPx;
    if (d >= end) return false;  // on or past the border: the carpet's side
    // The disc's centre has no outward direction: any will do, the whole panel is judged.
    if (d < 0.5) dx = 1.0, dy = 0.0;
    else dx /= d, dy /= d;
    return wallAlong(p, dx, dy, disc, marginPx, pixels);  // the walk outwards
}

void EnclosedPanels::reset(const BallDisc& disc, double marginPx, int minDirections, const PanelPixels& pixels)
{
    disc_ = disc;
    minDirections_ = minDirections;
    margin_ = marginPx;
    pixels_ = &pixels;
    const int reach = int(std::ceil(disc.radius));
    x0_ = int(std::floor(disc.x)) - reach;
    y0_ = int(std::floor(disc.y)) - reach;
    side_ = 2 * reach + 2;
    memo_.assign(std::size_t(side_) * std::size_t(side_), std::int8_t(-1));
}

bool EnclosedPanels::at(cv::Point p) const
{
    const int ix = p.x - x0_;
    const int iy = p.y - y0_;
    if (!pixels_ || ix < 0 || iy < 0 || ix >= side_ || iy >= side_) return false;  // outside the disc
    std::int8_t& m = memo_[std::size_t(iy) * std::size_t(side_) + std::size_t(ix)];
    if (m < 0)
        m = onEnclosedPanel(p, disc_, margin_, *pixels_) ||
                    (minDirections_ > 0 && enclosedFrom(p, disc_, margin_, minDirections_, *pixels_))
                ? 1
                : 0;
    return m == 1;
}

}  // namespace omnitune
