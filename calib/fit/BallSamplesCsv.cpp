#include "calib/fit/BallSamplesCsv.h"

namespace omnitune {

BallSamplesParse parseBallSamples(const std::string& text, const std::string& fileName)
{
    BallSamplesParse parse;
    NumberCsv csv = parseNumberCsv(text, fileName, {"distance_px", "distance_m", "radius_px"});
    const bool inPixels = csv.has("distance_px");
    if (!csv.has("radius_px") || (!inPixels && !csv.has("distance_m"))) {
        parse.error = CsvIssue{CsvIssueKind::MissingColumn, fileName, csv.headerLine,
                               std::string(csv.headerLine == 0 ? "the file holds no samples; " : "") +
                                   "the first line must name the columns distance_px,radius_px or distance_m,radius_px"};
        return parse;
    }
    parse.warnings = std::move(csv.warnings);
    for (const NumberCsvRow& row : csv.rows) {
        BallSampleRow s;
        s.line = row.line;
        s.inMetres = !inPixels;
        s.distance = row.values.at(inPixels ? "distance_px" : "distance_m");
        s.radiusPx = row.values.at("radius_px");
        if (s.distance < 0 || !(s.radiusPx > 0)) {
            parse.warnings.push_back(
                {CsvIssueKind::BadValue, fileName, row.line, "a negative distance or a radius not above 0; row skipped"});
            continue;
        }
        parse.rows.push_back(s);
    }
    return parse;
}

BallSamplesParse loadBallSamples(const std::string& path)
{
    return loadCsvFile<BallSamplesParse>(path, parseBallSamples);
}

std::vector<BallSample> toBallSamples(const std::vector<BallSampleRow>& rows, const DistanceMap& map)
{
    std::vector<BallSample> samples;
    for (const auto& r : rows) samples.push_back({r.inMetres ? map.ballPixels(r.distance) : r.distance, r.radiusPx, -1, std::nullopt});
    return samples;
}

}  // namespace omnitune
