#include "calib/fit/NumberCsv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
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

std::vector<std::string> cellsOf(const std::string& line)
{
    std::vector<std::string> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) return cells;
        start = comma + 1;
    }
}

std::optional<double> number(const std::string& cell)
{
    const char* first = cell.data();
    const char* last = first + cell.size();
    if (first != last && *first == '+') ++first;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(first, last, v);
    if (cell.empty() || ec != std::errc() || end != last || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace

std::string_view csvIssueKindName(CsvIssueKind kind)
{
    switch (kind) {
    case CsvIssueKind::FileUnreadable: return "file unreadable";
    case CsvIssueKind::MissingColumn: return "missing column";
    case CsvIssueKind::UnknownColumn: return "unknown column";
    case CsvIssueKind::WrongColumnCount: return "wrong column count";
    case CsvIssueKind::BadNumber: return "bad number";
    case CsvIssueKind::BadValue: return "bad value";
    }
    return "?";
}

std::string CsvIssue::toString() const
{
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line);
    return s + ": " + message;
}

bool NumberCsv::has(const std::string& column) const
{
    return std::find(columns.begin(), columns.end(), column) != columns.end();
}

NumberCsv parseNumberCsv(const std::string& text, const std::string& fileName, const std::vector<std::string>& known)
{
    NumberCsv csv;
    std::stringstream in(text);
    std::string raw;
    int lineNo = 0;
    std::vector<std::string> header;
    while (std::getline(in, raw)) {
        ++lineNo;
        const std::string line = trim(raw);
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> cells = cellsOf(line);
        if (header.empty()) {
            header = cells;
            csv.headerLine = lineNo;
            for (const std::string& h : header) {
                if (std::find(known.begin(), known.end(), h) != known.end()) csv.columns.push_back(h);
                else csv.warnings.push_back({CsvIssueKind::UnknownColumn, fileName, lineNo, "unknown column '" + h + "' ignored"});
            }
            continue;
        }
        if (cells.size() != header.size()) {
            csv.warnings.push_back({CsvIssueKind::WrongColumnCount, fileName, lineNo,
                                    std::to_string(cells.size()) + " cells where the header has " +
                                        std::to_string(header.size()) + "; row skipped"});
            continue;
        }
        NumberCsvRow row;
        row.line = lineNo;
        bool good = true;
        for (std::size_t i = 0; i < header.size() && good; ++i) {
            if (std::find(known.begin(), known.end(), header[i]) == known.end()) continue;
            const auto v = number(cells[i]);
            if (!v) {
                csv.warnings.push_back({CsvIssueKind::BadNumber, fileName, lineNo,
                                        header[i] + ": \"" + cells[i] + "\" is not a number; row skipped"});
                good = false;
            } else {
                row.values[header[i]] = *v;
            }
        }
        if (good) csv.rows.push_back(row);
    }
    return csv;
}

std::optional<std::string> readTextFile(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) return std::nullopt;
    std::stringstream text;
    text << file.rdbuf();
    if (file.bad()) return std::nullopt;
    return text.str();
}

}  // namespace omnitune
