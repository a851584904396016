#include "core/FrameColour.h"

#include "core/ColorLut.h"

#include <algorithm>

namespace omnitune {

Hsv bgrToHsv(std::uint8_t b, std::uint8_t g, std::uint8_t r)
{
    const int mx = std::max({int(b), int(g), int(r)});
    const int mn = std::min({int(b), int(g), int(r)});
    const int d = mx - mn;
    Hsv out;
    out.v = mx;
    out.s = mx == 0 ? 0 : (255 * d + mx / 2) / mx;
    if (d == 0) return out;
    double h;  // degrees
    if (mx == r)
        h = 60.0 * (int(g) - int(b)) / d;
    else if (mx == g)
        h = 120.0 + 60.0 * (int(b) - int(r)) / d;
    else
        h = 240.0 + 60.0 * (int(r) - int(g)) / d;
    if (h < 0) h += 360.0;
    out.h = int(h / 2.0 + 0.5) % 180;
    return out;
}

std::array<std::uint8_t, 3> FrameColour::bgrAt(int x, int y) const
{
    if (format_ == PixelFormat::Bgr8) {
        const cv::Vec3b& p = frame_.at<cv::Vec3b>(y, x);
        return {p[0], p[1], p[2]};
    }
    // UYVY: U0 Y0 V0 Y1 per pixel pair; the pair shares U and V.
    const std::uint8_t* pair = frame_.ptr<std::uint8_t>(y) + 2 * (x & ~1);
    return yuvToBgr(pair[(x & 1) ? 3 : 1], pair[0], pair[2]);
}

}  // namespace omnitune
