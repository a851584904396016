#include "core/HallRay.h"

#include "core/RoundHalfAway.h"

#include <climits>
#include <cmath>
#include <cstdlib>

namespace omnitune {

namespace {

// Ray steps: half a pixel, as the circularity's own walk.
constexpr double kStep = 0.5;
// px past the band's end where the floor's colour is read: whole pixels, the first one past any
// blur the band still holds.
constexpr double kFloorFromPx = 1.0;
constexpr double kFloorToPx = 3.0;
// Carpet pixels in a row that end the floor: one is a speck of noise in a dim floor.
constexpr int kCarpetRun = 2;

cv::Point along(const HallRaySpan& s, double r)
{
    return {roundHalfAway(s.centre.x + r * s.ca), roundHalfAway(s.centre.y + r * s.sa)};
}

// Whether the ray from the band's end on reaches the rim over floor (no carpet, no mask).
bool runsOutOverFloor(const HallRaySpan& s, double reachPx, const HallPixels& pixels)
{
    int carpetRun = 0;  // carpet pixels in a row
    cv::Point last(INT_MIN, INT_MIN);
    for (double r = s.rMaxPx + kStep; r <= s.rMaxPx + reachPx + 1e-9; r += kStep) {
        const cv::Point p = along(s, r);
        if (p == last) continue;
        last = p;
        if (!pixels.known(p)) return pixels.pastRim(p);
        carpetRun = pixels.carpet(p) ? carpetRun + 1 : 0;
        if (carpetRun >= kCarpetRun) return false;
    }
    return false;  // the rim is farther: a robot or a blob on the carpet, not the hall
}

}  // namespace

HallRay hallRay(const HallRaySpan& span, double rMinPx, double reachPx, double minStep, const HallPixels& pixels)
{
    HallRay ray;
    if (!runsOutOverFloor(span, reachPx, pixels)) return ray;
    // The floor's colour, just past the band (the ball's blur ends inside it).
    double floorBgr[3] = {0, 0, 0};
    int n = 0;
    for (double d = kFloorFromPx; d <= kFloorToPx; d += 1.0) {
        const cv::Point p = along(span, span.rMaxPx + d);
        if (!pixels.known(p)) continue;
        const auto c = pixels.bgr(p);
        for (int k = 0; k < 3; ++k) floorBgr[k] += c[k];
        ++n;
    }
    if (n == 0) return ray;  // the band reaches the rim: nothing to compare with
    for (double& f : floorBgr) f /= n;
    ray.overFloor = true;
    double lastBall = -1.0;
    for (double r = kStep; r <= span.rMaxPx + 1e-9; r += kStep) {
        const cv::Point p = along(span, r);
        if (!pixels.known(p)) continue;
        const auto c = pixels.bgr(p);
        const double step =
            std::abs(c[0] - floorBgr[0]) + std::abs(c[1] - floorBgr[1]) + std::abs(c[2] - floorBgr[2]);
        if (step >= minStep) lastBall = r;
    }
    // The colour must end inside the band: one that still differs at its end runs on into
    // something that is not the floor, or the floor's samples are its blur.
    if (lastBall >= 0.0 && lastBall + kStep >= rMinPx && lastBall + kStep <= span.rMaxPx) {
        ray.border = true;
        ray.borderPx = lastBall + kStep;
    }
    return ray;
}

}  // namespace omnitune
