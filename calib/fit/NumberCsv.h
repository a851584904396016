#pragma once
// The calibration files (distance points, ball samples) are CSVs of numbers under a header
// line that names the columns. This is their shared pure parser: text in, the numbers of the
// columns the caller knows plus line-numbered typed warnings out. Blank lines and lines
// starting with '#' are skipped; a row with a bad number or the wrong number of cells is
// skipped with a warning, so one typo does not cost the other rows. Numbers are read without
// the locale (the GUI may run under one with a decimal comma).
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace omnitune {

enum class CsvIssueKind {
    FileUnreadable,    // the file cannot be read
    MissingColumn,     // no header, or it lacks a column the file needs
    UnknownColumn,     // warning: a header column the reader does not know; ignored
    WrongColumnCount,  // warning: a row with more or fewer cells than the header; skipped
    BadNumber,         // warning: a cell that should be a number is not; skipped
    BadValue,          // warning: a number that is not allowed (negative distance, ...); skipped
};

std::string_view csvIssueKindName(CsvIssueKind kind);

struct CsvIssue {
    CsvIssueKind kind = CsvIssueKind::BadNumber;
    std::string file;     // as given by the caller
    int line = 0;         // 1-based, 0 when not about a line
    std::string message;  // what is wrong

    // "points.csv:4: distance_m: \"1,5\" is not a number; row skipped"
    std::string toString() const;
};

struct NumberCsvRow {
    int line = 0;
    std::map<std::string, double> values;  // known column -> number
};

struct NumberCsv {
    std::vector<std::string> columns;  // the known columns the header has
    int headerLine = 0;                // 0: the text holds no header line
    std::vector<NumberCsvRow> rows;
    std::vector<CsvIssue> warnings;

    bool has(const std::string& column) const;
};

// Only the `known` columns are read (as numbers); other columns get one UnknownColumn warning.
// Whether the header has the columns the caller needs is the caller's to check.
NumberCsv parseNumberCsv(const std::string& text, const std::string& fileName, const std::vector<std::string>& known);

// The file's text, or nothing when it cannot be read.
std::optional<std::string> readTextFile(const std::string& path);

// Reads `path` and hands its text to `parse(text, path)`; an unreadable file is the result's
// error (a FileUnreadable CsvIssue).
template <class Parse, class ParseText>
Parse loadCsvFile(const std::string& path, ParseText parse)
{
    const auto text = readTextFile(path);
    if (!text) {
        Parse result;
        result.error = CsvIssue{CsvIssueKind::FileUnreadable, path, 0, "cannot be read"};
        return result;
    }
    return parse(*text, path);
}

}  // namespace omnitune
