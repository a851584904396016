#include "core/LineShare.h"

#include "core/Geometry.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

DiscShares discShares(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                      double radiusPx, const PaleLine& pale)
{
    CV_Assert(classes.type() == CV_8UC1 && radiusPx >= 0.0);
    const int reach = int(std::floor(radiusPx));
    int all = 0;
    int used = 0;
    int line = 0;
    int panel = 0;
    for (int yy = y - reach; yy <= y + reach; ++yy) {
        const bool rowInside = yy >= 0 && yy < classes.rows;
        const std::uint8_t* cls = rowInside ? classes.ptr<std::uint8_t>(yy) : nullptr;
        for (int xx = x - reach; xx <= x + reach; ++xx) {
            if ((xx - x) * (xx - x) + (yy - y) * (yy - y) > radiusPx * radiusPx) continue;
            ++all;
            if (!rowInside || xx < 0 || xx >= classes.cols || !geometry.isUsed(xx, yy)) continue;
            ++used;
            const std::uint8_t id = cls[xx];
            line += roles.line(id) || pale.at(xx, yy, id, roles);
            panel += roles.black(id) || roles.is(id, ColourRole::Ball) || roles.is(id, ColourRole::Marker);
        }
    }
    const double unusedPct = all ? 100.0 * (all - used) / all : 100.0;
    if (!used) return {0.0, 0.0, unusedPct};
    return {100.0 * line / used, 100.0 * panel / used, unusedPct};
}

double lineSharePct(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                    double radiusPx)
{
    return discShares(classes, geometry, roles, x, y, radiusPx).linePct;
}

}  // namespace omnitune
