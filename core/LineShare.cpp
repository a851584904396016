#include "core/LineShare.h"

#include "core/Geometry.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

double lineSharePct(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                    double radiusPx)
{
    CV_Assert(classes.type() == CV_8UC1 && radiusPx >= 0.0);
    const int reach = int(std::floor(radiusPx));
    int used = 0;
    int line = 0;
    for (int yy = std::max(0, y - reach); yy <= std::min(classes.rows - 1, y + reach); ++yy) {
        const std::uint8_t* cls = classes.ptr<std::uint8_t>(yy);
        for (int xx = std::max(0, x - reach); xx <= std::min(classes.cols - 1, x + reach); ++xx) {
            if ((xx - x) * (xx - x) + (yy - y) * (yy - y) > radiusPx * radiusPx || !geometry.isUsed(xx, yy)) continue;
            ++used;
            line += roles.line(cls[xx]);
        }
    }
    return used ? 100.0 * line / used : 0.0;
}

}  // namespace omnitune
