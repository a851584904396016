#pragma once
// POINTS.csv for the distance-map fit: image points whose ground distance is known. A header
// names the columns, in any order:
//   radius_px,distance_m       the image distance from the mirror centre is known, or
//   x,y,distance_m             the image point (px), converted to a radius with the centre
// Blank lines and lines starting with '#' are skipped. Pure parser: text in, points plus
// line-numbered typed warnings out; a bad row is skipped with a warning, only an unusable header
// fails the file.
#include "calib/fit/DistanceMapFit.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace omnitune {

enum class PointsIssueKind {
    FileUnreadable,    // the file cannot be read
    MissingColumn,     // the header lacks distance_m, or both radius_px and x,y
    UnknownColumn,     // warning: a header column this build does not know; ignored
    WrongColumnCount,  // warning: a row with more or fewer cells than the header; skipped
    BadNumber,         // warning: a cell that should be a number is not; skipped
    BadValue,          // warning: a negative radius or distance; skipped
};

std::string_view pointsIssueKindName(PointsIssueKind kind);

struct PointsIssue {
    PointsIssueKind kind = PointsIssueKind::BadNumber;
    std::string file;     // as given by the caller
    int line = 0;         // 1-based, 0 when not about a line
    std::string message;  // what is wrong

    // "points.csv:4: distance_m: \"1,5\" is not a number; row skipped"
    std::string toString() const;
};

struct CalibrationPoint {
    bool fromImagePoint = false;  // x, y given (radius from the centre), else radius_px
    double xPx = 0.0;
    double yPx = 0.0;
    double radiusPx = 0.0;        // meaningful when !fromImagePoint
    double distanceM = 0.0;
    int line = 0;
};

struct CalibrationPointsParse {
    std::vector<CalibrationPoint> points;  // in file order; meaningful only when ok()
    std::vector<PointsIssue> warnings;
    std::optional<PointsIssue> error;

    bool ok() const { return !error.has_value(); }
    // True when any point is an image point (x,y): the centre is needed.
    bool needsCentre() const;
};

// `fileName` only labels the messages.
CalibrationPointsParse parseCalibrationPoints(const std::string& text, const std::string& fileName);
// Reads and parses `path`; an unreadable file is the error.
CalibrationPointsParse loadCalibrationPoints(const std::string& path);

// The fit's input: image points become their distance from `centre`.
std::vector<DistancePoint> toDistancePoints(const std::vector<CalibrationPoint>& points, cv::Point2d centre);

}  // namespace omnitune
