#pragma once
// The config a careful team would set from its measurements (CameraMeasurements.h), made by the
// fits of calib/fit/: the mirror rim gives size, centre and outer radius (RimFit, a margin inside
// the rim); the robot body the inner radius (BodyFit, else the mask's central blob); the marks
// the distance map (DistanceMapFit's best monotone polynomial, or the marks' mean radius per
// distance when that reproduces them better, the viewpoint height as measured); the ball's circles the ball model (BallModelFit, the clamps
// set to the measured radii plus a margin; its radial squash from the distance map, BallSquashFit); the painted mask is the mask. The Hough's radial
// areas and near-robot radius, the radial sensors' ring and the OpenCV Hough's radius range are
// rescaled to the fitted ring and ball. Colours and thresholds stay as in `base`.
#include "calib/fit/BallModelFit.h"
#include "calib/fit/BodyFit.h"
#include "calib/fit/CameraMeasurements.h"
#include "calib/fit/DistanceMapFit.h"
#include "calib/fit/RimFit.h"
#include "core/Config.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct MeasuredCalibrationOptions {
    double rimMarginPx = RimFitOptions{}.marginPx;  // outer radius this far inside the found rim (RimFit.h)
    double bodyMarginPx = 3.0;     // inner radius this far outside the robot body
    double maxRadiusMarginPx = 3.0;// ball.max_radius: the largest measured radius plus this
    double minRadiusMarginPx = 1.0;// ball.min_radius: the smallest measured radius minus this (>= 2 px)
    int tableSize = 24;            // distance-map table points
};

struct MeasuredCalibration {
    Config config;                 // meaningful only when ok()
    RimFit rim;
    std::optional<BodyFit> body;   // empty when the inner radius came from the mask
    DistanceMapFit distanceMap;          // the best polynomial (degree 3..6), when one fits
    int distanceMapDegree = 0;
    bool distanceMapFromRings = false;   // the config's table is the marks' mean radius per distance
    double distanceMapRmsCm = 0.0;       // how far the config's map misses the marks
    BallModelFit ballModel;
    std::vector<BallSample> ballSamples;  // distances from the fitted centre
    std::optional<std::string> error;

    bool ok() const { return !error.has_value(); }
};

MeasuredCalibration calibrateFromMeasurements(const Config& base, const CameraMeasurements& measurements,
                                              const MeasuredCalibrationOptions& options = {});

// "distance_px,radius_px" lines of the calibration's ball samples (calib/fit/BallSamplesCsv.h).
std::string ballSamplesCsv(const std::vector<BallSample>& samples);

}  // namespace omnitune
