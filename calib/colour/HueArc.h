#pragma once
// A hue range seen as an arc on the hue circle (OpenCV's 0..179): where it starts and how many
// hue steps it covers. HsvRange's hMin > hMax wrap is awkward to grow, cut or measure; the arc
// makes those one formula each.
#include "core/HsvRange.h"

namespace omnitune {

inline constexpr int kHueSteps = 180;

struct HueArc {
    int start = 0;          // first hue of the arc, 0..179
    int length = kHueSteps; // hue steps covered, 1..180 (180: every hue)

    static HueArc of(const HsvRange& r);
    // Writes the arc into r's hMin/hMax (a full arc as 0..179, never a wrap).
    void applyTo(HsvRange& r) const;
    // Steps from the arc's start to h going up (0..179); h is inside when this is below length.
    int offsetOf(int h) const;
    bool contains(int h) const { return offsetOf(h) < length; }
    bool full() const { return length >= kHueSteps; }
};

// The shortest arc that covers both arcs.
HueArc unite(const HueArc& a, const HueArc& b);

// A hue 0..179 from any integer (wraps).
inline int wrapHue(int h) { return ((h % kHueSteps) + kHueSteps) % kHueSteps; }

}  // namespace omnitune
