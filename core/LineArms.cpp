#include "core/LineArms.h"

#include "core/Geometry.h"
#include "core/RoundHalfAway.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace omnitune {

namespace {

// Rays: two per pixel of circumference at the arm's far end, so that a 2 px line there is met
// by a ray that stays inside it.
int armRayCount(double farPx) { return std::clamp(int(std::ceil(4.0 * M_PI * farPx)), 32, 720); }

}  // namespace

LineArms lineArmsAround(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                        double radiusPx, double reach, double lateralPx, const PaleLine& pale)
{
    CV_Assert(classes.type() == CV_8UC1 && radiusPx > 0.0 && reach >= 1.0 && lateralPx >= 0.0);
    const double farPx = reach * radiusPx;
    const int rays = armRayCount(farPx);
    auto lineAt = [&](double px, double py) {
        const int ix = roundHalfAway(px);
        const int iy = roundHalfAway(py);
        if (ix < 0 || iy < 0 || ix >= classes.cols || iy >= classes.rows || !geometry.isUsed(ix, iy)) return false;
        const std::uint8_t id = classes.ptr<std::uint8_t>(iy)[ix];
        return roles.line(id) || pale.at(ix, iy, id, roles);
    };
    auto isArm = [&](int i) {
        const double a = 2.0 * M_PI * i / rays;
        const double ca = std::cos(a);
        const double sa = std::sin(a);
        for (double r = radiusPx; r <= farPx + 1e-9; r += 0.5) {
            const double px = x + r * ca;
            const double py = y + r * sa;
            if (!lineAt(px, py) && !lineAt(px - lateralPx * sa, py + lateralPx * ca) &&
                !lineAt(px + lateralPx * sa, py - lateralPx * ca))
                return false;
        }
        return true;
    };
    // Start the circular scan at a ray that is no arm, so that no arm is split in two.
    int start = -1;
    for (int i = 0; i < rays && start < 0; ++i)
        if (!isArm(i)) start = i;
    LineArms arms;
    if (start < 0) return arms;
    constexpr int kMaxArms = 8;  // more than three already make a junction
    std::array<double, kMaxArms> direction{};
    int runStart = -1;
    for (int k = 1; k <= rays && arms.count < kMaxArms; ++k) {
        const int i = (start + k) % rays;
        const bool arm = k < rays && isArm(i);
        if (arm && runStart < 0) runStart = k;
        if (!arm && runStart >= 0) {
            direction[std::size_t(arms.count++)] = 2.0 * M_PI * (start + 0.5 * (runStart + k - 1)) / rays;
            runStart = -1;
        }
    }
    // Rounding to pixels splits one arm into neighbouring groups of rays: groups closer than
    // the angle the arm's tolerance (a line pixel plus lateralPx either side) subtends at the
    // circle are one arm.
    const double mergeRad = 2.0 * std::atan((lateralPx + 1.0) / radiusPx);
    int merged = 0;
    for (int i = 0; i < arms.count; ++i) {
        const double gap = i == 0 ? 2.0 * M_PI : direction[std::size_t(i)] - direction[std::size_t(merged - 1)];
        if (gap < mergeRad) continue;  // the same arm as the previous group
        direction[std::size_t(merged++)] = direction[std::size_t(i)];
    }
    if (merged > 1 && direction[0] + 2.0 * M_PI - direction[std::size_t(merged - 1)] < mergeRad) --merged;  // around 0
    arms.count = merged;
    for (int i = 0; i < arms.count; ++i)
        for (int j = i + 1; j < arms.count; ++j) {
            double d = std::fmod(std::abs(direction[std::size_t(i)] - direction[std::size_t(j)]), 2.0 * M_PI);
            d = std::min(d, 2.0 * M_PI - d);
            arms.minSeparationDeg = std::min(arms.minSeparationDeg, d * 180.0 / M_PI);
        }
    return arms;
}

}  // namespace omnitune
