#include "calib/fit/CalibrationPointsCsv.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace omnitune {

namespace {

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> splitCells(const std::string& line)
{
    std::vector<std::string> cells;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ',')) cells.push_back(trim(cell));
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
}

std::optional<double> number(const std::string& cell)
{
    if (cell.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    if (*end != '\0' || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace

std::string_view pointsIssueKindName(PointsIssueKind kind)
{
    switch (kind) {
    case PointsIssueKind::FileUnreadable: return "file unreadable";
    case PointsIssueKind::MissingColumn: return "missing column";
    case PointsIssueKind::UnknownColumn: return "unknown column";
    case PointsIssueKind::WrongColumnCount: return "wrong column count";
    case PointsIssueKind::BadNumber: return "bad number";
    case PointsIssueKind::BadValue: return "bad value";
    }
    return "?";
}

std::string PointsIssue::toString() const
{
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line);
    return s + ": " + message;
}

bool CalibrationPointsParse::needsCentre() const
{
    for (const auto& p : points)
        if (p.fromImagePoint) return true;
    return false;
}

CalibrationPointsParse parseCalibrationPoints(const std::string& text, const std::string& fileName)
{
    CalibrationPointsParse parse;
    std::stringstream in(text);
    std::string raw;
    int lineNo = 0;
    std::vector<std::string> header;
    int colRadius = -1, colX = -1, colY = -1, colDistance = -1;
    const auto issue = [&](PointsIssueKind kind, const std::string& message) {
        return PointsIssue{kind, fileName, lineNo, message};
    };
    while (std::getline(in, raw)) {
        ++lineNo;
        const std::string line = trim(raw);
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> cells = splitCells(line);
        if (header.empty()) {
            header = cells;
            std::vector<PointsIssue> unknown;
            for (std::size_t i = 0; i < header.size(); ++i) {
                const std::string& h = header[i];
                if (h == "radius_px") colRadius = int(i);
                else if (h == "x" || h == "x_px") colX = int(i);
                else if (h == "y" || h == "y_px") colY = int(i);
                else if (h == "distance_m") colDistance = int(i);
                else unknown.push_back(issue(PointsIssueKind::UnknownColumn, "unknown column '" + h + "' ignored"));
            }
            if (colDistance < 0 || (colRadius < 0 && (colX < 0 || colY < 0))) {
                parse.error = issue(PointsIssueKind::MissingColumn,
                                    "the first line must name the columns radius_px,distance_m or x,y,distance_m (got '" +
                                        line + "')");
                return parse;
            }
            parse.warnings.insert(parse.warnings.end(), unknown.begin(), unknown.end());
            continue;
        }
        if (cells.size() != header.size()) {
            parse.warnings.push_back(issue(PointsIssueKind::WrongColumnCount,
                                           std::to_string(cells.size()) + " cells where the header has " +
                                               std::to_string(header.size()) + "; row skipped"));
            continue;
        }
        CalibrationPoint p;
        p.line = lineNo;
        p.fromImagePoint = colRadius < 0;
        bool good = true;
        const auto read = [&](int col, double& out) {
            if (!good) return;
            const auto v = number(cells[std::size_t(col)]);
            if (!v) {
                parse.warnings.push_back(issue(PointsIssueKind::BadNumber, header[std::size_t(col)] + ": \"" +
                                                                               cells[std::size_t(col)] +
                                                                               "\" is not a number; row skipped"));
                good = false;
                return;
            }
            out = *v;
        };
        if (p.fromImagePoint) {
            read(colX, p.xPx);
            read(colY, p.yPx);
        } else {
            read(colRadius, p.radiusPx);
        }
        read(colDistance, p.distanceM);
        if (!good) continue;
        if (p.distanceM < 0 || p.radiusPx < 0) {
            parse.warnings.push_back(issue(PointsIssueKind::BadValue, "a negative radius or distance; row skipped"));
            continue;
        }
        parse.points.push_back(p);
    }
    if (header.empty()) {
        lineNo = 0;
        parse.error = issue(PointsIssueKind::MissingColumn,
                            "the file holds no points; the first line must name the columns radius_px,distance_m or x,y,distance_m");
    }
    return parse;
}

CalibrationPointsParse loadCalibrationPoints(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        CalibrationPointsParse parse;
        parse.error = PointsIssue{PointsIssueKind::FileUnreadable, path, 0, "cannot be read"};
        return parse;
    }
    std::stringstream text;
    text << file.rdbuf();
    return parseCalibrationPoints(text.str(), path);
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
