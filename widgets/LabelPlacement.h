#pragma once
// Where the overlay's text labels go when candidates crowd (several near the robot, all with
// "A3 98/100/96"): each label takes the first free spot around its circle, nearest first, then
// farther out with a leader line back to the circle; a label with no free spot left is not
// drawn (its circle still is, and the pane's tooltip explains it). No two placed labels
// overlap or touch (kLabelGapPx apart at least). Presentation only: widget pixels in, rectangles out.
#include <QPointF>
#include <QRectF>
#include <QSizeF>

#include <vector>

namespace omnitune {

struct LabelRequest {
    QPointF centre;  // the circle the label belongs to, widget px
    double radius = 0.0;
    QSizeF size;     // the label's text box
};

struct LabelSpot {
    bool placed = false;
    QRectF box;           // where the text goes, when placed
    bool leader = false;  // moved away from its circle: draw a line from the circle to the box
};

// Free space kept between two labels (widget px): two labels that touch read as one line
// ("A5 98/100/56A5 94/100/43"), and which circle each belongs to is lost.
constexpr double kLabelGapPx = 3.0;

// Places the labels in the given order (first = most important, placed first). Labels stay
// inside `bounds` (the pane) and off the `reserved` boxes (labels placed before, a title).
// Circles are avoided when there is room, never at the cost of a label.
std::vector<LabelSpot> placeLabels(const std::vector<LabelRequest>& labels, const QRectF& bounds,
                                   const std::vector<QRectF>& reserved = {});

// The point of `box` nearest to `p` (where a leader line ends).
QPointF nearestPoint(const QRectF& box, QPointF p);

}  // namespace omnitune
