#include "core/RimTest.h"

#include "core/BallEllipse.h"
#include "core/Geometry.h"
#include "core/RoundHalfAway.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace omnitune {

RimClosure rimClosure(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                      double radius, double squash, double bandPx, double minInwardCos, bool skipInnerField)
{
    RimClosure out;
    const double ix = geometry.options().centerX - x;
    const double iy = geometry.options().centerY - y;
    const double il = std::hypot(ix, iy);
    if (!(il > 0.0) || !(radius > 0.0)) return out;
    const int rays = std::max(16, int(std::ceil(2.0 * M_PI * radius)));
    const double q = squash > 0.0 ? squash : 1.0;
    for (int i = 0; i < rays; ++i) {
        const double a = 2.0 * M_PI * i / rays;
        const double ca = std::cos(a);
        const double sa = std::sin(a);
        const double cr = -(ca * ix + sa * iy) / il;  // along the outward radial axis
        if (-cr < minInwardCos) continue;
        const double ct = (sa * ix - ca * iy) / il;  // along the tangential one
        // The ellipse of the same area as the circle, squashed radially (BallModel::squashAt).
        const double border = radius * squashedReach(cr, ct, q);
        const double rMin = std::max(0.5, border - bandPx);
        const double rMax = border + bandPx;
        bool judged = true;
        bool closed = false;
        for (double r = 0.5; r <= rMax + 1e-9; r += 0.5) {
            const int px = roundHalfAway(x + r * ca);
            const int py = roundHalfAway(y + r * sa);
            if (px < 0 || py < 0 || px >= classes.cols || py >= classes.rows || !geometry.isUsed(px, py)) {
                judged = false;  // a rod or the body in the way: says nothing
                break;
            }
            const std::uint8_t cls = classes.ptr<std::uint8_t>(py)[px];
            if (roles.field(cls)) {
                if (skipInnerField && r < rMin - 1e-9) continue;
                closed = r >= rMin - 1e-9;
                break;
            }
        }
        out.judged += judged;
        out.closed += judged && closed;
    }
    return out;
}

double rimArcRunPx(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, double x, double y,
                   double maxEachWayPx, double carpetPx, bool maskedMirrors)
{
    const double cx = geometry.options().centerX;
    const double cy = geometry.options().centerY;
    const double d = std::hypot(x - cx, y - cy);
    if (!(d > 1.0)) return 0.0;
    const double a0 = std::atan2(y - cy, x - cx);
    auto pixelAlong = [&](double way, double s) {
        const double a = a0 + way * s / d;
        return cv::Point(roundHalfAway(cx + d * std::cos(a)), roundHalfAway(cy + d * std::sin(a)));
    };
    auto inImage = [&](cv::Point p) { return p.x >= 0 && p.y >= 0 && p.x < classes.cols && p.y < classes.rows; };
    // What the arc holds `s` px along it `way`: nothing (unprocessed or off the image), or the class.
    auto classAlong = [&](double way, double s) -> std::optional<std::uint8_t> {
        const cv::Point p = pixelAlong(way, s);
        if (!inImage(p) || !geometry.isUsed(p.x, p.y)) return std::nullopt;
        return classes.ptr<std::uint8_t>(p.y)[p.x];
    };
    // Carpet that goes on: field here and at every px on out to carpetPx (unprocessed ends it too).
    auto carpetGoesOn = [&](double way, double s) {
        for (double t = 1.0; t <= carpetPx + 1e-9; t += 1.0) {
            const std::optional<std::uint8_t> cls = classAlong(way, s + t);
            if (!cls) break;
            if (!roles.field(*cls)) return false;
        }
        return true;
    };
    const cv::Mat& maskedInRing = geometry.maskedInRing();
    double runs[2] = {0.0, 0.0};
    bool atMask[2] = {false, false};
    for (int k = 0; k < 2; ++k) {
        const double way = k == 0 ? 1.0 : -1.0;
        double s = 0.5;
        for (; s <= maxEachWayPx + 1e-9; s += 0.5) {
            const std::optional<std::uint8_t> cls = classAlong(way, s);
            if (!cls) {
                const cv::Point p = pixelAlong(way, s);
                atMask[k] = !maskedInRing.empty() && inImage(p) && maskedInRing.ptr<std::uint8_t>(p.y)[p.x] != 0;
                break;
            }
            if (roles.field(*cls) && carpetGoesOn(way, s)) break;
        }
        runs[k] = std::min(s, maxEachWayPx);
    }
    if (maskedMirrors && atMask[0] != atMask[1]) {
        const double open = atMask[0] ? runs[1] : runs[0];
        runs[0] = std::max(runs[0], open);
        runs[1] = std::max(runs[1], open);
    }
    return runs[0] + runs[1];
}

double rimWidestArcRunPx(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                         double maxEachWayPx, double carpetPx, double offsetPx, bool maskedMirrors)
{
    double widest = rimArcRunPx(classes, geometry, roles, x, y, maxEachWayPx, carpetPx, maskedMirrors);
    const double dx = x - geometry.options().centerX;
    const double dy = y - geometry.options().centerY;
    const double d = std::hypot(dx, dy);
    if (!(d > 1.0)) return widest;
    for (double o = 1.0; o <= offsetPx + 1e-9; o += 1.0)
        for (const double way : {1.0, -1.0}) {
            const double k = way * o / d;
            widest = std::max(widest, rimArcRunPx(classes, geometry, roles, x + k * dx, y + k * dy, maxEachWayPx,
                                                  carpetPx, maskedMirrors));
        }
    return widest;
}

}  // namespace omnitune
