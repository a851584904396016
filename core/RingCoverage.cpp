#include "core/RingCoverage.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace omnitune {

namespace {

// Length of the chord of a circle of radius r at vertical offset dy from its centre, clipped
// to the columns [0, width] (centre at cx).
double clippedChord(double r, double dy, double cx, double width)
{
    if (std::abs(dy) >= r) return 0.0;
    const double half = std::sqrt(r * r - dy * dy);
    return std::max(0.0, std::min(cx + half, width) - std::max(cx - half, 0.0));
}

}  // namespace

double ringShareInImage(const GeometryOptions& g)
{
    const double r0 = std::max(0.0, g.innerRadius);
    const double r1 = g.outerRadius;
    const double ringArea = M_PI * (r1 * r1 - r0 * r0);
    if (!std::isfinite(ringArea) || !(ringArea > 0.0)) return 0.0;
    if (!std::isfinite(g.centerX) || !std::isfinite(g.centerY)) return 0.0;
    // Midpoint rule over the rows the ring and the image share: 8 samples per pixel row is far
    // finer than the question ("mostly off the image?") needs. Integrating only those rows keeps
    // the step count bounded by the image, whatever radius a hand-edited config holds.
    const double top = std::max(0.0, g.centerY - r1);
    const double bottom = std::min(double(g.imageHeight), g.centerY + r1);
    if (!(bottom > top)) return 0.0;
    const int steps = int(std::clamp(std::ceil(8.0 * (bottom - top)), 64.0, 1.0e6));
    const double h = (bottom - top) / steps;
    double inside = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double dy = top + (i + 0.5) * h - g.centerY;
        inside += (clippedChord(r1, dy, g.centerX, g.imageWidth) - clippedChord(r0, dy, g.centerX, g.imageWidth)) * h;
    }
    return std::clamp(inside / ringArea, 0.0, 1.0);
}

double maskProcessedShare(const cv::Mat& mask, const GeometryOptions& g)
{
    if (mask.empty()) return 1.0;
    const double r0 = g.innerRadius * g.innerRadius, r1 = g.outerRadius * g.outerRadius;
    long ring = 0, processed = 0;
    for (int y = 0; y < mask.rows; ++y) {
        const std::uint8_t* m = mask.ptr<std::uint8_t>(y);
        const double dy = y - g.centerY;
        for (int x = 0; x < mask.cols; ++x) {
            const double dx = x - g.centerX, d2 = dx * dx + dy * dy;
            if (d2 < r0 || d2 > r1) continue;
            ++ring;
            processed += m[x] != 0;
        }
    }
    return ring > 0 ? double(processed) / double(ring) : 1.0;
}

}  // namespace omnitune
