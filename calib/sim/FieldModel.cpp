#include "calib/sim/FieldModel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace omnitune {

namespace {

void requirePositive(double value, const char* name)
{
    if (!(value > 0)) throw std::invalid_argument(std::string("field.") + name + " must be positive");
}

}  // namespace

FieldModel::FieldModel(const FieldDimensions& d) : dims_(d)
{
    requirePositive(d.length, "length");
    requirePositive(d.width, "width");
    requirePositive(d.lineWidth, "line_width");
    requirePositive(d.centerCircleRadius, "center_circle_radius");
    requirePositive(d.goalAreaDepth, "goal_area_depth");
    requirePositive(d.goalAreaWidth, "goal_area_width");
    requirePositive(d.penaltyAreaDepth, "penalty_area_depth");
    requirePositive(d.penaltyAreaWidth, "penalty_area_width");
    requirePositive(d.cornerArcRadius, "corner_arc_radius");
    requirePositive(d.goalWidth, "goal_width");
    requirePositive(d.goalHeight, "goal_height");
    if (d.goalAreaDepth >= d.penaltyAreaDepth || d.goalAreaWidth >= d.penaltyAreaWidth ||
        d.penaltyAreaWidth >= d.width || 2 * d.penaltyAreaDepth >= d.length ||
        2 * d.centerCircleRadius >= d.width)
        throw std::invalid_argument("field: goal area, penalty area and centre circle do not fit the field");
    if (d.carpetMargin < 0) throw std::invalid_argument("field.carpet_margin must not be negative");

    const double hx = d.length / 2;
    const double hy = d.width / 2;
    // Outer lines and centre line.
    segments_.push_back({{-hx, -hy}, {hx, -hy}});
    segments_.push_back({{hx, -hy}, {hx, hy}});
    segments_.push_back({{hx, hy}, {-hx, hy}});
    segments_.push_back({{-hx, hy}, {-hx, -hy}});
    segments_.push_back({{0, -hy}, {0, hy}});
    arcs_.push_back({{0, 0}, d.centerCircleRadius, 0, 2 * M_PI});
    spots_.push_back({0, 0});
    for (double side : {-1.0, 1.0}) {
        const double gx = side * hx;
        // Goal and penalty areas: three sides each, open on the goal line.
        for (const auto& [depth, w] : {std::pair{d.goalAreaDepth, d.goalAreaWidth},
                                       std::pair{d.penaltyAreaDepth, d.penaltyAreaWidth}}) {
            const double ix = gx - side * depth;
            segments_.push_back({{gx, -w / 2}, {ix, -w / 2}});
            segments_.push_back({{ix, -w / 2}, {ix, w / 2}});
            segments_.push_back({{ix, w / 2}, {gx, w / 2}});
        }
        spots_.push_back({gx - side * d.penaltyMarkDistance, 0});

        FieldGoal goal;
        const double postY = d.goalWidth / 2 + d.postRadius;
        const double postX = gx + side * d.postRadius;
        const double backX = gx + side * (d.postRadius + d.goalDepth);
        goal.leftPost = {postX, side * postY};
        goal.rightPost = {postX, -side * postY};
        goal.net = {{{postX, -postY}, {backX, -postY}}, {{backX, -postY}, {backX, postY}}, {{backX, postY}, {postX, postY}}};
        goal.height = d.goalHeight;
        goal.postRadius = d.postRadius;
        goals_.push_back(goal);
    }
    // Corner arcs, a quarter circle into the field at each corner.
    const double r = d.cornerArcRadius;
    arcs_.push_back({{-hx, -hy}, r, 0, M_PI / 2});
    arcs_.push_back({{hx, -hy}, r, M_PI / 2, M_PI});
    arcs_.push_back({{hx, hy}, r, M_PI, 1.5 * M_PI});
    arcs_.push_back({{-hx, hy}, r, 1.5 * M_PI, 2 * M_PI});
}

double FieldModel::distanceTo(const FieldSegment& s, const cv::Point2d& p)
{
    const cv::Point2d ab = s.b - s.a;
    const double len2 = ab.dot(ab);
    const double t = len2 > 0 ? std::clamp((p - s.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return cv::norm(p - (s.a + t * ab));
}

double FieldModel::distanceTo(const FieldArc& a, const cv::Point2d& p)
{
    const cv::Point2d v = p - a.centre;
    double angle = std::atan2(v.y, v.x);
    // Bring the angle into [startAngle, startAngle + 2 pi) to test the span.
    angle = a.startAngle + std::fmod(std::fmod(angle - a.startAngle, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
    if (angle <= a.endAngle) return std::abs(cv::norm(v) - a.radius);
    const cv::Point2d s = a.centre + a.radius * cv::Point2d(std::cos(a.startAngle), std::sin(a.startAngle));
    const cv::Point2d e = a.centre + a.radius * cv::Point2d(std::cos(a.endAngle), std::sin(a.endAngle));
    return std::min(cv::norm(p - s), cv::norm(p - e));
}

double FieldModel::distanceToLines(const cv::Point2d& p) const
{
    double best = std::numeric_limits<double>::infinity();
    for (const FieldSegment& s : segments_) best = std::min(best, distanceTo(s, p));
    for (const FieldArc& a : arcs_) best = std::min(best, distanceTo(a, p));
    // A spot is a filled disc: its "line centre" lies half a line width inside its rim.
    const double spotInset = dims_.spotRadius - 0.5 * dims_.lineWidth;
    for (const cv::Point2d& s : spots_) best = std::min(best, std::max(0.0, cv::norm(p - s) - spotInset));
    return best;
}

cv::Rect2d FieldModel::carpetBounds() const
{
    const double hx = dims_.length / 2 + dims_.carpetMargin;
    const double hy = dims_.width / 2 + dims_.carpetMargin;
    return {-hx, -hy, 2 * hx, 2 * hy};
}

bool FieldModel::onCarpet(const cv::Point2d& p) const
{
    const cv::Rect2d b = carpetBounds();
    return p.x >= b.x && p.x <= b.x + b.width && p.y >= b.y && p.y <= b.y + b.height;
}

}  // namespace omnitune
