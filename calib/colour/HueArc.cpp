#include "calib/colour/HueArc.h"

#include <algorithm>

namespace omnitune {

HueArc HueArc::of(const HsvRange& r)
{
    const int len = r.hMin <= r.hMax ? r.hMax - r.hMin + 1 : kHueSteps - r.hMin + r.hMax + 1;
    return {wrapHue(r.hMin), std::clamp(len, 1, kHueSteps)};
}

void HueArc::applyTo(HsvRange& r) const
{
    if (full()) {
        r.hMin = 0;
        r.hMax = kHueSteps - 1;
        return;
    }
    r.hMin = start;
    r.hMax = wrapHue(start + length - 1);
}

int HueArc::offsetOf(int h) const { return wrapHue(h - start); }

HueArc unite(const HueArc& a, const HueArc& b)
{
    // Either arc's start begins the union; the other end is whichever arc reaches farther.
    const HueArc fromA{a.start, std::max(a.length, a.offsetOf(b.start) + b.length)};
    const HueArc fromB{b.start, std::max(b.length, b.offsetOf(a.start) + a.length)};
    HueArc u = fromA.length <= fromB.length ? fromA : fromB;
    if (u.length >= kHueSteps) u = HueArc{0, kHueSteps};
    return u;
}

}  // namespace omnitune
