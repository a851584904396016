#pragma once
// What a team measures on its robot before a match, kept together so the geometry can be fitted
// from it (MeasuredCalibration.h): marks on the floor at known ground distances located in the
// image, the ball laid at known distances and its circle located in the image, a few frames of
// the empty field while the robot turns (mirror rim and robot body), the mask they painted
// (support rods, the body) and the height of the mirror's viewpoint measured with a tape.
//
// On disk (a session's measurements/ folder):
//   calibration_points.csv  x,y,distance_m                 (CalibrationPointsCsv.h)
//   ball_marks.csv          x,y,radius_px,distance_m       the ball's circle as located
//   empty_NNN.png           empty-field frames
//   mask.png                255 = process
//   viewpoint_height.txt    metres, one number
#include "calib/fit/CalibrationPointsCsv.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct BallMark {
    double x = 0.0, y = 0.0;  // px, the ball's centre as located in the image
    double radiusPx = 0.0;    // px, its radius as located
    double distanceM = 0.0;   // m, ground distance robot centre to ball centre (tape)
};

struct CameraMeasurements {
    std::vector<CalibrationPoint> points;  // image points (x, y) of marks at known distances
    std::vector<BallMark> balls;
    std::vector<cv::Mat> emptyFrames;      // BGR
    cv::Mat mask;                          // CV_8UC1, 255 = process; may be empty
    double viewpointHeight = 0.0;          // m, 0 = not measured
};

// Writes the files above into `folder` (created). Returns an error message or nullopt.
std::optional<std::string> saveCameraMeasurements(const CameraMeasurements& m, const std::string& folder);
// Reads them back; missing optional files (mask, viewpoint height) stay empty. nullopt and
// `error` set when a required file (points, ball marks, at least one empty frame) is missing.
std::optional<CameraMeasurements> loadCameraMeasurements(const std::string& folder, std::string& error);

}  // namespace omnitune
