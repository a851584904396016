#include "calib/fit/CalibrationPointsCsv.h"

#include <cmath>

namespace omnitune {

bool CalibrationPointsParse::needsCentre() const
{
    for (const auto& p : points)
        if (p.fromImagePoint) return true;
    return false;
}

CalibrationPointsParse parseCalibrationPoints(const std::string& text, const std::string& fileName)
{
    CalibrationPointsParse parse;
    NumberCsv csv = parseNumberCsv(text, fileName, {"radius_px", "x", "y", "distance_m"});
    const bool byRadius = csv.has("radius_px");
    if (!csv.has("distance_m") || (!byRadius && !(csv.has("x") && csv.has("y")))) {
        parse.error = CsvIssue{CsvIssueKind::MissingColumn, fileName, csv.headerLine,
                               csv.headerLine == 0 ? "the file holds no points; the first line must name the columns "
                                                     "radius_px,distance_m or x,y,distance_m"
                                                   : "the first line must name the columns radius_px,distance_m or "
                                                     "x,y,distance_m"};
        return parse;
    }
    parse.warnings = std::move(csv.warnings);
    for (const NumberCsvRow& row : csv.rows) {
        CalibrationPoint p;
        p.line = row.line;
        p.fromImagePoint = !byRadius;
        p.distanceM = row.values.at("distance_m");
        if (byRadius) {
            p.radiusPx = row.values.at("radius_px");
        } else {
            p.xPx = row.values.at("x");
            p.yPx = row.values.at("y");
        }
        if (p.distanceM < 0 || p.radiusPx < 0) {
            parse.warnings.push_back({CsvIssueKind::BadValue, fileName, row.line, "a negative radius or distance; row skipped"});
            continue;
        }
        parse.points.push_back(p);
    }
    return parse;
}

CalibrationPointsParse loadCalibrationPoints(const std::string& path)
{
    return loadCsvFile<CalibrationPointsParse>(path, parseCalibrationPoints);
}

std::vector<DistancePoint> toDistancePoints(const std::vector<CalibrationPoint>& points, cv::Point2d centre)
{
    std::vector<DistancePoint> out;
    for (const auto& p : points) {
        const double r = p.fromImagePoint ? std::hypot(p.xPx - centre.x, p.yPx - centre.y) : p.radiusPx;
        out.push_back({r, p.distanceM, p.line});
    }
    return out;
}

}  // namespace omnitune
