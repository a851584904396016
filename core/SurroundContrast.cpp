#include "core/SurroundContrast.h"

#include "core/FrameColour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace omnitune {
namespace {
// In expected radii: the disc well inside the ball's blurred border, and a ring clear of it.
constexpr double kSurroundInside = 0.7;
constexpr double kSurroundFrom = 1.4;
constexpr double kSurroundTo = 2.2;
// px added to the ring's bounds: a far ball's blur spreads a pixel or more past its radius.
constexpr double kSurroundFromPx = 1.0;
constexpr double kSurroundToPx = 1.5;
// Share of the ring that must be off the carpet for the comparison to say something.
constexpr double kSurroundMinShare = 0.1;
}  // namespace

std::optional<double> surroundContrast(const FrameColour& colour, const cv::Mat& classes, const cv::Mat& used,
                                       const ColourRoles& roles, int x, int y, double radius)
{
    const double inside = kSurroundInside * radius;
    const double from = kSurroundFrom * radius + kSurroundFromPx;
    const double to = kSurroundTo * radius + kSurroundToPx;
    const int reach = int(std::ceil(to));
    double in[3] = {0, 0, 0};
    double out[3] = {0, 0, 0};
    int inCount = 0;
    int outCount = 0;
    int ringCount = 0;
    for (int yy = std::max(0, y - reach); yy <= std::min(classes.rows - 1, y + reach); ++yy) {
        const std::uint8_t* cls = classes.ptr<std::uint8_t>(yy);
        const std::uint8_t* u = used.ptr<std::uint8_t>(yy);
        for (int xx = std::max(0, x - reach); xx <= std::min(classes.cols - 1, x + reach); ++xx) {
            if (!u[xx]) continue;
            const double d = std::hypot(xx - x, yy - y);
            const bool isInside = d <= inside;
            const bool inRing = d >= from && d <= to;
            if (!isInside && !inRing) continue;
            if (inRing) {
                ++ringCount;
                if (roles.field(cls[xx])) continue;
            }
            const auto bgr = colour.bgrAt(xx, yy);
            double* sum = isInside ? in : out;
            for (int k = 0; k < 3; ++k) sum[k] += bgr[k];
            ++(isInside ? inCount : outCount);
        }
    }
    if (inCount == 0 || ringCount == 0 || outCount < kSurroundMinShare * ringCount) return std::nullopt;
    double step = 0.0;
    for (int k = 0; k < 3; ++k) step += std::abs(in[k] / inCount - out[k] / outCount);
    return step;
}

}  // namespace omnitune
