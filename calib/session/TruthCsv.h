#pragma once
// truth.csv: the ground truth of a session, one row per annotated frame (not every frame
// needs one). Pure parser and serializer: text in, rows plus line-numbered typed warnings
// out. A bad row is skipped with a warning rather than failing the file, because one typo in
// a hand-edited annotation should not cost the other rows; only an unusable header fails.
#include "calib/sim/RobotPose.h"
#include "calib/session/SessionIssue.h"

#include <opencv2/core.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct TruthRow {
    int frame = 0;             // 0-based frame index in the session
    bool ballVisible = false;  // the ball can be seen in this frame
    // The ball, meaningful only when ballVisible; in the same frames as core's BallDetection
    // and the simulator's GroundTruth.
    double px = 0.0;        // ball centre in the image, px
    double py = 0.0;        // px
    double radiusPx = 0.0;  // px, > 0
    double xM = 0.0;        // m, robot frame: the robot's right, image +x
    double yM = 0.0;        // m, robot frame: the robot's forward, image -y
    std::optional<RobotPose> robot;  // field-frame pose (RobotPose.h); empty: unknown
};

// What a truth value may be. A row outside these is refused (BadValue, with its line), so a
// typo like radius 1e30 never reaches the window (which would spin drawing it) or the
// evaluation (which would average it into inf).
struct TruthLimits {
    // px of the session's frames; empty when unknown, and then kSessionMaxFrameSide bounds.
    // The ball centre must lie in the image, and its radius below half the shorter side: a
    // larger ball would not fit in the frame, whatever the ball model says.
    cv::Size frameSize;
    // m: the farthest a ball or a robot may be from the robot or the field centre. No camera
    // sees a ball a field's diagonal (~25 m) away; the bound only catches garbage.
    double maxDistanceM = 100.0;
};

struct TruthParse {
    std::map<int, TruthRow> rows;        // by frame; meaningful only when ok()
    int dataRows = 0;                    // non-blank lines after the header, usable or not
    std::vector<SessionIssue> warnings;  // one per skipped row or odd column, with its line
    std::optional<SessionIssue> error;   // the header is missing or lacks a required column

    bool ok() const { return !error.has_value(); }
};

// `fileName` only labels the messages.
TruthParse parseTruthCsv(const std::string& text, const std::string& fileName, const TruthLimits& limits = {});

// "frame,ball_visible,px,py,radius_px,x_m,y_m,robot_x,robot_y,robot_heading" (no newline).
std::string truthCsvHeader();

// One data line without the newline. Numbers are written in the shortest form that reads
// back to the same double; ball cells are empty when the ball is not visible, robot cells
// when the pose is unknown.
std::string formatTruthRow(const TruthRow& row);

// The whole file: header, then one line per row in frame order, each ending in '\n'.
std::string serializeTruthCsv(const std::map<int, TruthRow>& rows);

}  // namespace omnitune
