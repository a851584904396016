#pragma once
// One cell of the optics simulator's condition grid (ball kind x light x distractors x carpet x
// mirror x image size): renders its frames through the catadioptric camera and returns them with
// the optics' truth and the config a team would fit from the camera's measurements. The quality
// gate iterates over cells; the fitted config never sees the simulator's truth.
#include "calib/fit/MeasuredCalibration.h"
#include "calib/session/TruthCsv.h"
#include "calib/sim/optics/OpticsRenderer.h"
#include "calib/sim/BallKind.h"
#include "core/Config.h"

#include <opencv2/core.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace omnitune {

enum class OpticsLight { Dim, Normal, Bright, Uneven };
enum class OpticsDistractors { None, RobotsFeetShadow, NoiseBlur, RodsOcclusion };
// Teal: a cyan-green turf whose hue lies past the default green box (and in the default cyan
// marker box), as the carpets of issue 10's real frames; the colour tours use it, the quality
// matrix does not (its colours are the defaults).
enum class OpticsCarpet { Green, CyanGreen, DarkGreen, Teal };
enum class OpticsMirror { Hyperbolic, Spherical };

// How a cell's frames choose the ball's direction from the robot. Spread: golden-angle steps
// from frame to frame, so a tour of many frames sees every direction, but one or two frames see
// only the first steps (two narrow sectors, the same in every cell). Random: each frame draws its
// own from its seed, so cells of one or two frames together still cover the whole image, and a
// ball behind a rod is looked for from a random direction (the quality matrix).
enum class OpticsDirections { Spread, Random };

struct OpticsCell {
    BallKind ball = BallKind::Orange;
    OpticsLight light = OpticsLight::Normal;
    OpticsDistractors distractors = OpticsDistractors::None;
    OpticsCarpet carpet = OpticsCarpet::Green;
    OpticsMirror mirror = OpticsMirror::Hyperbolic;
    cv::Size image{640, 480};
    bool ballPresent = true;
    int frames = 4;            // ball positions spread 0.5..5 m and over all image directions
    unsigned seed = 1;
    OpticsDirections directions = OpticsDirections::Spread;
};

struct OpticsCellFrames {
    std::vector<cv::Mat> frames;          // BGR
    std::map<int, TruthRow> truth;        // one row per frame (calib/session/TruthCsv.h)
    // Frames whose ball shows some pixels but is not visible by the truth's rule (more than half
    // hidden, or its centre off the frame): its robot-frame position, m. A detection there is
    // no false positive (judge's hiddenBallM).
    std::map<int, cv::Point2d> hiddenBalls;
    Config fittedConfig;                  // from the camera's measurements, never the truth
    std::string calibrationError;         // empty, or why the fit failed (fittedConfig is then `base`)
    FieldDimensions field;                // the field the scenes stand on (where a truth row's ball lies)
    double ballRadiusM = 0.0;             // the scenes' ball radius, m
};

// Renders one cell. Calibrates the cell's camera (image size + mirror) from its measurements
// starting from `base`; the calibration is cached per camera so many cells stay cheap.
// Thread-safe.
OpticsCellFrames renderCell(const OpticsCell& cell, const Config& base = {});

// "yellow-white/dim/rods/640x480" (carpet and mirror are appended when not the defaults:
// ".../cyan-green/spherical").
std::string opticsCellName(const OpticsCell& cell);

// Names used by the command line and opticsCellName: "dim", "normal", "bright", "uneven";
// "none", "robots", "noise", "rods"; "green", "cyan-green", "dark-green", "teal"; "hyperbolic",
// "spherical".
std::string opticsLightName(OpticsLight light);
std::string opticsDistractorsName(OpticsDistractors distractors);
std::string opticsCarpetName(OpticsCarpet carpet);
std::string opticsMirrorName(OpticsMirror mirror);

// The parts renderCell uses, for tools that need more than frames (omnitune-sim --optics).
// Support rods of a cell's camera: 3 (640x480) or 4 (480x480) with RodsOcclusion, else none.
int opticsCellRods(const OpticsCell& cell);
CatadioptricCameraParams opticsCellCameraParams(const OpticsCell& cell);

// A cell's camera from the process-wide cache: its renderer, the measurements a team takes of
// it, and the calibration fitted from them starting from `base`. Pointers stay valid for the
// process' lifetime.
struct OpticsCamera {
    const OpticsRenderer* renderer = nullptr;
    const CameraMeasurements* measurements = nullptr;
    std::shared_ptr<const MeasuredCalibration> calibration;
};
OpticsCamera opticsCellCamera(const OpticsCell& cell, const Config& base = {});

// Frame `frame` of a cell: the robot somewhere on the field, the ball at a distance spread over
// 0.5..5 m across the cell's frames and a direction all around, the cell's light, carpet and
// distractors (robots + feet + head shadow, every third ball touching a line; noise + 7 px
// motion blur; rods, with balls partly behind a rod, behind a robot or touching our body).
OpticsScene opticsCellScene(const OpticsCell& cell, int frame, const OpticsRenderer& renderer);

// The truth.csv row of a rendered frame.
TruthRow toTruthRow(const OpticsTruth& truth, int frame, bool ballPresent);

}  // namespace omnitune
