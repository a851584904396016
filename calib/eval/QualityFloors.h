#pragma once
// The quality gate's floors file (tests/quality_gate_floors.csv): for each algorithm and metric
// the target and the floor the test asserts (what the detector measured when the file
// was written, less a margin), plus the matrix settings and the frames' pixel format the numbers
// were measured with (tests/quality_gate_floors_uyvy.csv holds the robot's YUV 4:2:2 figures).
#include "calib/eval/QualityMatrix.h"
#include "calib/eval/QualityRun.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

// Metrics: "detection_pct" (ball frames found, all ball cells), "cell_min_detection_pct" (the
// worst ball cell), "false_positive_pct" (frames with a false positive, ball-free cells
// included), "range_std_cm" (std of the range error of balls within 4 m).
struct QualityFloor {
    std::string algorithm;           // "specific", "opencv", "combined"
    std::string metric;
    bool atLeast = true;             // "min": measured >= floor; "max": measured <= floor
    std::optional<double> target;    // issue 9's goal; empty: none
    std::optional<double> floor;     // what the test asserts; empty: not asserted
    std::optional<double> measured;  // when the file was written (for the reader)
};

struct QualityFloorsFile {
    QualityMatrixOptions matrix;  // frames_per_cell, ball_free_frames_per_cell, seed
    PixelFormat pixelFormat = PixelFormat::Bgr8;  // pixel_format: what the detector read (absent: bgr8)
    std::vector<QualityFloor> floors;
};

std::optional<QualityFloorsFile> parseQualityFloors(const std::string& text, std::string& error);
std::string serializeQualityFloors(const QualityFloorsFile& file);

// The metric for one variant of a run; empty when it cannot be measured (no ball frames, no
// range sample) or the metric name is unknown.
std::optional<double> qualityMetric(const QualityRun& run, std::size_t variant, const std::string& metric);

// Floors from a run of algorithmVariants(): each metric as measured less a margin (2 points of
// detection, one frame of a cell, 0.3 points of false positives, 1 cm or a fifth of range std),
// with issue 9's targets.
QualityFloorsFile floorsFromRun(const QualityRun& run, const QualityMatrixOptions& matrix,
                                PixelFormat pixelFormat = PixelFormat::Bgr8);

struct QualityFloorCheck {
    QualityFloor floor;
    std::optional<double> measured;
    bool passed = true;  // also true when the floor is empty (not asserted)
    std::string line;    // "specific detection_pct 38.2 >= floor 36.0 (target 97: 58.8 to go)"
};
// Checks every floor whose algorithm is one of the run's variants (by name).
std::vector<QualityFloorCheck> checkQualityFloors(const QualityRun& run, const QualityFloorsFile& file);

}  // namespace omnitune
