#pragma once
// The RoboCup Middle Size League field as geometry in field metres: origin at the centre spot,
// x along the length (towards the +x goal), y across, z up. Lines are centre-line segments,
// arcs and spots of one line width; goals are posts and nets standing on the goal lines.
// Dimensions default to the 18 x 12 m field of the thesis era (MSL rules 2009).
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

struct FieldDimensions {
    double length = 18.0;             // m, goal line to goal line (line centres)
    double width = 12.0;              // m, touch line to touch line (line centres)
    double lineWidth = 0.125;         // m
    double centerCircleRadius = 2.0;  // m
    double goalAreaDepth = 0.75;      // m, from the goal line into the field
    double goalAreaWidth = 3.5;       // m
    double penaltyAreaDepth = 2.25;   // m
    double penaltyAreaWidth = 6.5;    // m
    double cornerArcRadius = 0.75;    // m
    double penaltyMarkDistance = 3.0; // m from the goal line
    double spotRadius = 0.075;        // m; centre spot and penalty marks
    double goalWidth = 2.0;           // m between the posts' inner faces
    double goalDepth = 0.6;           // m, net behind the goal line
    double goalHeight = 1.0;          // m
    double postRadius = 0.0625;       // m
    double carpetMargin = 1.0;        // m of carpet beyond the outer lines; then the hall floor
};

struct FieldSegment {
    cv::Point2d a;
    cv::Point2d b;
};

// Counter-clockwise from startAngle to endAngle (rad, from +x; endAngle > startAngle).
struct FieldArc {
    cv::Point2d centre;
    double radius = 0.0;
    double startAngle = 0.0;
    double endAngle = 0.0;
};

// One goal: two posts and the net (back and sides) as vertical walls from the ground up.
struct FieldGoal {
    cv::Point2d leftPost;   // post centres
    cv::Point2d rightPost;
    std::vector<FieldSegment> net;  // ground footprints of the net walls
    double height = 0.0;
    double postRadius = 0.0;
};

class FieldModel {
public:
    // Throws std::invalid_argument when a dimension is not positive or the areas do not fit.
    explicit FieldModel(const FieldDimensions& dimensions = {});

    const FieldDimensions& dimensions() const { return dims_; }
    const std::vector<FieldSegment>& segments() const { return segments_; }
    const std::vector<FieldArc>& arcs() const { return arcs_; }
    const std::vector<cv::Point2d>& spots() const { return spots_; }
    const std::vector<FieldGoal>& goals() const { return goals_; }

    // Distance (m) from `p` to the nearest line centre (segment, arc, or spot edge): the point
    // is painted white where this is below lineWidth / 2.
    double distanceToLines(const cv::Point2d& p) const;
    bool onLine(const cv::Point2d& p) const { return distanceToLines(p) <= 0.5 * dims_.lineWidth; }
    // The carpet: the lines' rectangle plus carpetMargin all around.
    bool onCarpet(const cv::Point2d& p) const;
    cv::Rect2d carpetBounds() const;

    static double distanceTo(const FieldSegment& s, const cv::Point2d& p);
    static double distanceTo(const FieldArc& a, const cv::Point2d& p);

private:
    FieldDimensions dims_;
    std::vector<FieldSegment> segments_;
    std::vector<FieldArc> arcs_;
    std::vector<cv::Point2d> spots_;
    std::vector<FieldGoal> goals_;
};

}  // namespace omnitune
