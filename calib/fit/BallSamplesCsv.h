#pragma once
// SAMPLES.csv for the ball-model fit: balls measured in the image, e.g. a ball laid at measured
// distances around the robot, or what a simulator reports. A header names the columns:
//   distance_px,radius_px      image distance of the ball centre from the mirror centre, or
//   distance_m,radius_px       ground distance of the ball from the robot centre, converted to
//                              an image distance through the config's distance map
// Read by the shared pure parser (NumberCsv.h): a bad row is skipped with a line-numbered
// warning, only an unusable header fails the file.
#include "calib/fit/BallModelFit.h"
#include "calib/fit/NumberCsv.h"
#include "core/DistanceMap.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct BallSampleRow {
    bool inMetres = false;     // distance_m given, else distance_px
    double distance = 0.0;     // px or m
    double radiusPx = 0.0;
    int line = 0;
};

struct BallSamplesParse {
    std::vector<BallSampleRow> rows;  // in file order; meaningful only when ok()
    std::vector<CsvIssue> warnings;
    std::optional<CsvIssue> error;

    bool ok() const { return !error.has_value(); }
    bool needsDistanceMap() const { return !rows.empty() && rows.front().inMetres; }
};

// `fileName` only labels the messages.
BallSamplesParse parseBallSamples(const std::string& text, const std::string& fileName);
BallSamplesParse loadBallSamples(const std::string& path);

// The fit's input: ground distances become image distances through `map` (ball-height corrected).
std::vector<BallSample> toBallSamples(const std::vector<BallSampleRow>& rows, const DistanceMap& map);

}  // namespace omnitune
