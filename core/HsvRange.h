#pragma once
// An HSV box in OpenCV's 8-bit scale (H 0..179, S and V 0..255). A hue range with
// hMin > hMax wraps around 0/180, so red can be written as 170..10.

namespace omnitune {

struct HsvRange {
    bool enabled = true;  // a disabled box never matches
    int hMin = 0;         // hue lower bound, 0..179
    int hMax = 179;       // hue upper bound, 0..179 (below hMin: wraps through 0)
    int sMin = 0;         // saturation lower bound, 0..255
    int sMax = 255;       // saturation upper bound, 0..255
    int vMin = 0;         // value lower bound, 0..255
    int vMax = 255;       // value upper bound, 0..255

    bool containsHue(int h) const { return hMin <= hMax ? (h >= hMin && h <= hMax) : (h >= hMin || h <= hMax); }
    bool contains(int h, int s, int v) const
    {
        return enabled && containsHue(h) && s >= sMin && s <= sMax && v >= vMin && v <= vMax;
    }
};

inline bool operator==(const HsvRange& a, const HsvRange& b)
{
    return a.enabled == b.enabled && a.hMin == b.hMin && a.hMax == b.hMax && a.sMin == b.sMin && a.sMax == b.sMax &&
           a.vMin == b.vMin && a.vMax == b.vMax;
}
inline bool operator!=(const HsvRange& a, const HsvRange& b) { return !(a == b); }

}  // namespace omnitune
