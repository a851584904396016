#pragma once
// POINTS.csv for the distance-map fit: image points whose ground distance is known. A header
// names the columns, in any order:
//   radius_px,distance_m       the image distance from the mirror centre is known, or
//   x,y,distance_m             the image point (px), converted to a radius with the centre
// Read by the shared pure parser (NumberCsv.h): a bad row is skipped with a line-numbered
// warning, only an unusable header fails the file.
#include "calib/fit/DistanceMapFit.h"
#include "calib/fit/NumberCsv.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

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
    std::vector<CsvIssue> warnings;
    std::optional<CsvIssue> error;

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
