#pragma once
// truth.csv: the ground truth of a session, one row per annotated frame (not every frame
// needs one). Pure parser and serializer: text in, rows plus line-numbered typed warnings
// out. A bad row is skipped with a warning rather than failing the file, because one typo in
// a hand-edited annotation should not cost the other rows; only an unusable header fails.
#include "calib/sim/RobotPose.h"
#include "calib/session/SessionIssue.h"

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

struct TruthParse {
    std::map<int, TruthRow> rows;        // by frame; meaningful only when ok()
    std::vector<SessionIssue> warnings;  // one per skipped row or odd column, with its line
    std::optional<SessionIssue> error;   // the header is missing or lacks a required column

    bool ok() const { return !error.has_value(); }
};

// `fileName` only labels the messages.
TruthParse parseTruthCsv(const std::string& text, const std::string& fileName);

// "frame,ball_visible,px,py,radius_px,x_m,y_m,robot_x,robot_y,robot_heading" (no newline).
std::string truthCsvHeader();

// One data line without the newline. Numbers are written in the shortest form that reads
// back to the same double; ball cells are empty when the ball is not visible, robot cells
// when the pose is unknown.
std::string formatTruthRow(const TruthRow& row);

// The whole file: header, then one line per row in frame order, each ending in '\n'.
std::string serializeTruthCsv(const std::map<int, TruthRow>& rows);

}  // namespace omnitune
