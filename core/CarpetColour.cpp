#include "core/CarpetColour.h"

#include "core/Geometry.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

CarpetColour CarpetColour::around(const FrameColour& frame, const cv::Mat& classes, const Geometry& geometry,
                                  const ColourRoles& roles, int x, int y, double inner, double outer)
{
    CarpetColour cc;
    const int reach = int(std::ceil(outer));
    // About 20 samples across the ring's width: enough for a mean and spread, cheap for big balls.
    const int step = std::max(1, reach / 10);
    const double in2 = inner * inner;
    const double out2 = outer * outer;
    double sh = 0, ss = 0, sh2 = 0, ss2 = 0, sv = 0, sv2 = 0;
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
            sh += c.h;
            ss += c.s;
            sh2 += double(c.h) * c.h;
            ss2 += double(c.s) * c.s;
            sv += c.v;
            sv2 += double(c.v) * c.v;
            ++cc.samples_;
        }
    }
    if (cc.samples_ == 0) return cc;
    const double n = cc.samples_;
    cc.hue_ = sh / n;  // green hues (35..85) are far from the 0/180 wrap: a plain mean is right
    cc.sat_ = ss / n;
    cc.hueSpread_ = std::sqrt(std::max(0.0, sh2 / n - cc.hue_ * cc.hue_));
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

}  // namespace omnitune
