#include "widgets/LabelPlacement.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

// Spots around a circle at a gap `g` from its edge: right, above-right, below-right, left,
// above-left, below-left, above, below (reading order: to the right first, as before).
std::vector<QRectF> spotsAround(const LabelRequest& l, double g)
{
    const double r = l.radius + g;
    const double w = l.size.width(), h = l.size.height();
    const double cx = l.centre.x(), cy = l.centre.y();
    const double d = r * std::sqrt(0.5);  // the diagonal spots touch the circle at 45 degrees
    return {
        QRectF(cx + r, cy - h / 2, w, h),      QRectF(cx + d, cy - d - h, w, h), QRectF(cx + d, cy + d, w, h),
        QRectF(cx - r - w, cy - h / 2, w, h),  QRectF(cx - d - w, cy - d - h, w, h), QRectF(cx - d - w, cy + d, w, h),
        QRectF(cx - w / 2, cy - r - h, w, h),  QRectF(cx - w / 2, cy + r, w, h),
    };
}

// Whether `box` comes nearer than kLabelGapPx to any of `taken`.
bool overlapsAny(const QRectF& box, const std::vector<QRectF>& taken)
{
    const QRectF grown = box.adjusted(-kLabelGapPx, -kLabelGapPx, kLabelGapPx, kLabelGapPx);
    return std::any_of(taken.begin(), taken.end(), [&grown](const QRectF& t) { return t.intersects(grown); });
}

}  // namespace

QPointF nearestPoint(const QRectF& box, QPointF p)
{
    return {std::clamp(p.x(), box.left(), box.right()), std::clamp(p.y(), box.top(), box.bottom())};
}

std::vector<LabelSpot> placeLabels(const std::vector<LabelRequest>& labels, const QRectF& bounds,
                                   const std::vector<QRectF>& reserved)
{
    std::vector<LabelSpot> spots(labels.size());
    std::vector<QRectF> taken = reserved;  // and the labels placed so far
    std::vector<QRectF> circles;
    for (const LabelRequest& l : labels)
        circles.emplace_back(l.centre - QPointF(l.radius, l.radius), QSizeF(2 * l.radius, 2 * l.radius));
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const LabelRequest& l = labels[i];
        const double step = std::max(4.0, l.size.height());
        // Near the circle first; a leader line from the second ring on. Two passes: keep
        // clear of the other circles when possible, then of the other labels only.
        for (int pass = 0; pass < 2 && !spots[i].placed; ++pass) {
            for (int ring = 0; ring < 4 && !spots[i].placed; ++ring) {
                for (const QRectF& box : spotsAround(l, 3.0 + ring * step)) {
                    if (!bounds.contains(box) || overlapsAny(box, taken)) continue;
                    if (pass == 0) {
                        bool hitsCircle = false;
                        for (std::size_t j = 0; j < circles.size() && !hitsCircle; ++j)
                            hitsCircle = j != i && circles[j].intersects(box);
                        if (hitsCircle) continue;
                    }
                    spots[i] = {true, box, ring > 0};
                    taken.push_back(box);
                    break;
                }
            }
        }
    }
    return spots;
}

}  // namespace omnitune
