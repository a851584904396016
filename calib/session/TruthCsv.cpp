#include "calib/session/TruthCsv.h"

#include "calib/session/Session.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <sstream>

namespace omnitune {

namespace {

enum Column { Frame, BallVisible, Px, Py, RadiusPx, XM, YM, RobotX, RobotY, RobotHeading, ColumnCount };

const std::array<const char*, ColumnCount> kColumnNames = {"frame", "ball_visible", "px", "py", "radius_px",
                                                           "x_m",   "y_m",          "robot_x", "robot_y",
                                                           "robot_heading"};
constexpr int kFirstOptional = RobotX;  // the robot pose columns may be left out together

std::string trim(const std::string& s)
{
    const std::size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> splitCells(const std::string& line)
{
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
        cells.push_back(trim(line.substr(start, comma - start)));
    cells.push_back(trim(line.substr(start)));
    return cells;
}

// std::from_chars, not strtod: the GUI runs under the user's locale, where strtod may want
// a decimal comma.
std::optional<double> toDouble(const std::string& s)
{
    double v = 0.0;
    const char* end = s.data() + s.size();
    const auto [ptr, ec] = std::from_chars(s.data(), end, v);
    if (s.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<int> toInt(const std::string& s)
{
    int v = 0;
    const char* end = s.data() + s.size();
    const auto [ptr, ec] = std::from_chars(s.data(), end, v);
    if (s.empty() || ec != std::errc() || ptr != end) return std::nullopt;
    return v;
}

std::string formatDouble(double v)
{
    char buf[64];
    const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, ptr) : std::string("nan");
}

// The column and reason when a visible ball's centre or radius cannot be in the frame.
std::optional<std::pair<std::string, std::string>> outsideImage(double px, double py, double r,
                                                              const TruthLimits& limits)
{
    const bool known = limits.frameSize.width > 0 && limits.frameSize.height > 0;
    const int w = known ? limits.frameSize.width : kSessionMaxFrameSide;
    const int h = known ? limits.frameSize.height : kSessionMaxFrameSide;
    const std::string frame = known ? "the " + std::to_string(w) + "x" + std::to_string(h) + " frame"
                                    : std::string("0..") + std::to_string(kSessionMaxFrameSide) +
                                          " (the frame size is not known; no frame is larger)";
    if (!(px >= 0 && px < w)) return std::pair{std::string("px"), formatDouble(px) + " is outside " + frame};
    if (!(py >= 0 && py < h)) return std::pair{std::string("py"), formatDouble(py) + " is outside " + frame};
    const double maxR = std::min(w, h) / 2.0;
    if (r > maxR)
        return std::pair{std::string("radius_px"),
                         formatDouble(r) + " px does not fit in " +
                             (known ? frame : "any frame") + " (at most " + formatDouble(maxR) +
                             " px, half the shorter side)"};
    return std::nullopt;
}

// The first metre column whose value lies farther than `maxM`.
std::optional<int> tooFar(const std::array<std::optional<double>, ColumnCount>& value, double maxM)
{
    for (int c : {XM, YM, RobotX, RobotY})
        if (value[c] && std::abs(*value[c]) > maxM) return c;
    return std::nullopt;
}

}  // namespace

TruthParse parseTruthCsv(const std::string& text, const std::string& fileName, const TruthLimits& limits)
{
    TruthParse out;
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    auto warn = [&](SessionIssueKind kind, const std::string& column, const std::string& message) {
        out.warnings.push_back({kind, fileName, lineNo, column, message});
    };

    // Header: the first non-blank line. Columns may come in any order.
    bool haveHeader = false;
    while (!haveHeader && std::getline(in, line)) {
        ++lineNo;
        if (lineNo == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a spreadsheet's BOM
        haveHeader = !trim(line).empty();
    }
    if (!haveHeader) {
        out.error = SessionIssue{SessionIssueKind::ParseError, fileName, 0, "", "the file is empty: no header line"};
        return out;
    }
    const std::vector<std::string> header = splitCells(line);
    std::array<int, ColumnCount> at;
    at.fill(-1);
    for (std::size_t i = 0; i < header.size(); ++i) {
        int known = -1;
        for (int c = 0; c < ColumnCount; ++c)
            if (header[i] == kColumnNames[c]) known = c;
        if (known < 0) {
            warn(SessionIssueKind::UnknownColumn, header[i], "unknown column, ignored");
            continue;
        }
        if (at[known] >= 0) {
            out.error = SessionIssue{SessionIssueKind::ParseError, fileName, lineNo, header[i],
                                     "the header names this column twice"};
            return out;
        }
        at[known] = int(i);
    }
    for (int c = 0; c < kFirstOptional; ++c)
        if (at[c] < 0) {
            out.error = SessionIssue{SessionIssueKind::MissingColumn, fileName, lineNo, kColumnNames[c],
                                     std::string("the header has no '") + kColumnNames[c] +
                                         "' column (is the header line missing?); expected " + truthCsvHeader()};
            return out;
        }
    const int robotColumns = (at[RobotX] >= 0) + (at[RobotY] >= 0) + (at[RobotHeading] >= 0);
    const bool havePose = robotColumns == 3;
    if (robotColumns != 0 && !havePose)
        warn(SessionIssueKind::MissingColumn, "",
             "robot_x, robot_y and robot_heading come together; with only some of them the robot poses are ignored");

    std::map<int, int> lineOfFrame;
    while (std::getline(in, line)) {
        ++lineNo;
        if (trim(line).empty()) continue;
        ++out.dataRows;
        const std::vector<std::string> cells = splitCells(line);
        if (cells.size() != header.size()) {
            warn(SessionIssueKind::WrongColumnCount, "",
                 std::to_string(cells.size()) + " cells where the header has " + std::to_string(header.size()) +
                     "; row skipped");
            continue;
        }
        auto cell = [&](int c) -> const std::string& { return cells[std::size_t(at[c])]; };

        TruthRow row;
        const auto frame = toInt(cell(Frame));
        if (!frame) {
            warn(SessionIssueKind::BadNumber, "frame", "\"" + cell(Frame) + "\" is not a whole number; row skipped");
            continue;
        }
        if (*frame < 0) {
            warn(SessionIssueKind::BadValue, "frame", std::to_string(*frame) + " is negative; row skipped");
            continue;
        }
        row.frame = *frame;
        const auto visible = toDouble(cell(BallVisible));
        if (!visible) {
            warn(SessionIssueKind::BadNumber, "ball_visible", "\"" + cell(BallVisible) + "\" is not 0 or 1; row skipped");
            continue;
        }
        if (*visible != 0.0 && *visible != 1.0) {
            warn(SessionIssueKind::BadValue, "ball_visible", cell(BallVisible) + " is not 0 or 1; row skipped");
            continue;
        }
        row.ballVisible = *visible == 1.0;

        // Every non-empty cell must be a number; the ball cells must be filled when visible.
        std::array<std::optional<double>, ColumnCount> value;
        bool bad = false;
        for (int c = Px; c < ColumnCount && !bad; ++c) {
            if (at[c] < 0 || cell(c).empty()) continue;
            value[c] = toDouble(cell(c));
            if (!value[c]) {
                warn(SessionIssueKind::BadNumber, kColumnNames[c], "\"" + cell(c) + "\" is not a number; row skipped");
                bad = true;
            }
        }
        if (bad) continue;
        if (row.ballVisible) {
            for (int c = Px; c < kFirstOptional && !bad; ++c)
                if (!value[c]) {
                    warn(SessionIssueKind::BadValue, kColumnNames[c], "empty although ball_visible is 1; row skipped");
                    bad = true;
                }
            if (bad) continue;
            if (*value[RadiusPx] <= 0.0) {
                warn(SessionIssueKind::BadValue, "radius_px", cell(RadiusPx) + " is not above 0; row skipped");
                continue;
            }
            if (const auto why = outsideImage(*value[Px], *value[Py], *value[RadiusPx], limits)) {
                warn(SessionIssueKind::BadValue, why->first, why->second + "; row skipped");
                continue;
            }
            row.px = *value[Px];
            row.py = *value[Py];
            row.radiusPx = *value[RadiusPx];
            row.xM = *value[XM];
            row.yM = *value[YM];
        }
        if (const auto far = tooFar(value, limits.maxDistanceM)) {
            warn(SessionIssueKind::BadValue, kColumnNames[*far],
                 cell(*far) + " m is farther than " + formatDouble(limits.maxDistanceM) + " m; row skipped");
            continue;
        }
        if (havePose) {
            const int given = value[RobotX].has_value() + value[RobotY].has_value() + value[RobotHeading].has_value();
            if (given == 3) {
                row.robot = RobotPose{*value[RobotX], *value[RobotY], *value[RobotHeading]};
            } else if (given != 0) {
                warn(SessionIssueKind::BadValue, "",
                     "robot_x, robot_y and robot_heading must all be given or all be empty; row skipped");
                continue;
            }
        }
        if (const auto seen = lineOfFrame.find(row.frame); seen != lineOfFrame.end()) {
            warn(SessionIssueKind::DuplicateFrame, "frame",
                 "frame " + std::to_string(row.frame) + " already has a row on line " + std::to_string(seen->second) +
                     "; row skipped");
            continue;
        }
        lineOfFrame[row.frame] = lineNo;
        out.rows[row.frame] = row;
    }
    return out;
}

std::string truthCsvHeader()
{
    std::string h;
    for (const char* name : kColumnNames) h += (h.empty() ? "" : ",") + std::string(name);
    return h;
}

std::string formatTruthRow(const TruthRow& row)
{
    std::string s = std::to_string(row.frame) + (row.ballVisible ? ",1," : ",0,");
    if (row.ballVisible)
        s += formatDouble(row.px) + "," + formatDouble(row.py) + "," + formatDouble(row.radiusPx) + "," +
             formatDouble(row.xM) + "," + formatDouble(row.yM) + ",";
    else
        s += ",,,,,";
    if (row.robot)
        s += formatDouble(row.robot->x) + "," + formatDouble(row.robot->y) + "," + formatDouble(row.robot->heading);
    else
        s += ",,";
    return s;
}

std::string serializeTruthCsv(const std::map<int, TruthRow>& rows)
{
    std::string s = truthCsvHeader() + "\n";
    for (const auto& [frame, row] : rows) s += formatTruthRow(row) + "\n";
    return s;
}

}  // namespace omnitune
