#include "core/CarpetColour.h"

#include "core/Geometry.h"
#include "core/Pi.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace omnitune {

namespace {

// Hue h (0..179) as a point on the unit circle: the mean of these is the circular mean, so a
// red carpet whose hues straddle 0 / 179 averages to about 0, not to cyan's 90.
struct HueCircle {
    std::array<double, 256> cos{}, sin{};
    HueCircle()
    {
        for (int h = 0; h < 256; ++h) {
            cos[std::size_t(h)] = std::cos(2.0 * kPi * h / 180.0);
            sin[std::size_t(h)] = std::sin(2.0 * kPi * h / 180.0);
        }
    }
};
const HueCircle& hueCircle()
{
    static const HueCircle circle;
    return circle;
}

}  // namespace

CarpetColour CarpetColour::around(const FrameColour& frame, const cv::Mat& classes, const Geometry& geometry,
                                  const ColourRoles& roles, int x, int y, double inner, double outer)
{
    CarpetColour cc;
    const int reach = int(std::ceil(outer));
    // About 20 samples across the ring's width: enough for a mean and spread, cheap for big balls.
    const int step = std::max(1, reach / 10);
    const double in2 = inner * inner;
    const double out2 = outer * outer;
    const HueCircle& circle = hueCircle();
    double hc = 0, hs = 0, ss = 0, ss2 = 0, sv = 0, sv2 = 0;
    for (int dy = -reach; dy <= reach; dy += step) {
        const int yy = y + dy;
        if (yy < 0 || yy >= classes.rows) continue;
        const std::uint8_t* cls = classes.ptr<std::uint8_t>(yy);
        for (int dx = -reach; dx <= reach; dx += step) {
            const int xx = x + dx;
            const double d2 = double(dx) * dx + double(dy) * dy;
            if (xx < 0 || xx >= classes.cols || d2 < in2 || d2 > out2) continue;
            if (!roles.field(cls[xx]) || !geometry.isUsed(xx, yy)) continue;
            const Hsv c = frame.hsvAt(xx, yy);
            hc += circle.cos[c.h];
            hs += circle.sin[c.h];
            ss += c.s;
            ss2 += double(c.s) * c.s;
            sv += c.v;
            sv2 += double(c.v) * c.v;
            ++cc.samples_;
        }
    }
    if (cc.samples_ == 0) return cc;
    const double n = cc.samples_;
    // Circular mean and spread of the hues: the spread is the circular standard deviation
    // sqrt(-2 ln R) of the mean vector's length R, which is the ordinary one for a tight carpet.
    const double angle = std::atan2(hs / n, hc / n);
    cc.hue_ = std::fmod(angle * 180.0 / (2.0 * kPi) + 180.0, 180.0);
    const double r = std::clamp(std::hypot(hc / n, hs / n), 1e-12, 1.0);
    cc.hueSpread_ = std::sqrt(-2.0 * std::log(r)) * 180.0 / (2.0 * kPi);
    cc.sat_ = ss / n;
    cc.satSpread_ = std::sqrt(std::max(0.0, ss2 / n - cc.sat_ * cc.sat_));
    cc.val_ = sv / n;
    cc.valSpread_ = std::sqrt(std::max(0.0, sv2 / n - cc.val_ * cc.val_));
    return cc;
}

bool CarpetColour::matches(const Hsv& c, const CarpetTolerance& t) const
{
    if (!valid()) return true;
    double dh = std::abs(c.h - hue_);
    dh = std::min(dh, 180.0 - dh);
    const double hueTol = std::max(t.hue, t.sigmas * hueSpread_);
    const double satTol = std::max(t.saturation, t.sigmas * satSpread_);
    if (dh > hueTol || std::abs(c.s - sat_) > satTol) return false;
    return t.value <= 0 || std::abs(c.v - val_) <= std::max(t.value, t.sigmas * valSpread_);
}

bool CarpetColour::darker(double v, double tolerance, double sigmas) const
{
    return valid() && v < val_ - std::max(tolerance, sigmas * valSpread_);
}

}  // namespace omnitune
