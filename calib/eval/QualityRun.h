#pragma once
// Runs the detector over the quality matrix (calib/eval/QualityMatrix.h): renders each cell once
// through the optics simulator, runs every variant (an algorithm, optionally with config keys
// overridden) with the cell's fitted config, judges each frame by calib/eval/Evaluation.h's rules
// and tallies per cell; groups (per ball kind, light, distractors, size, overall) add cells up.
#include "calib/eval/BallPlace.h"
#include "calib/eval/ConfigOverride.h"
#include "calib/eval/Evaluation.h"
#include "calib/eval/FrameCrop.h"
#include "calib/eval/FrameDiagnosis.h"
#include "calib/sim/optics/OpticsCell.h"
#include "core/Algorithm.h"
#include "core/PixelFormat.h"
#include "core/Progress.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace omnitune {

// One way of running the detector: an algorithm plus config keys set on top of the fitted config.
struct QualityVariant {
    std::string name;  // "specific", or "specific, validation.first_edge_only=false"
    Algorithm algorithm = Algorithm::Combined;
    std::vector<ConfigOverride> overrides;
};

// specific, opencv, combined, each with the fitted config as it is.
std::vector<QualityVariant> algorithmVariants();
// For each algorithm in `algorithms`: every deviation switched to the thesis' value on its own,
// then all of them at once ("thesis" runs). Named "<algorithm>, <key>=<value>" and
// "<algorithm>, all thesis values".
std::vector<QualityVariant> deviationVariants(const std::vector<ConfigOverride>& deviations,
                                              const std::vector<Algorithm>& algorithms);

// One false-positive frame as the listing shows it (omnitune-eval --false-positives): what was
// detected, with its scores, the frame's truth, and the pixels around it.
struct FalsePositiveFrame {
    int frame = 0;                  // index in its cell
    bool ballVisible = false;       // a ball frame whose detection sat too far from the ball
    double truthPx = 0.0, truthPy = 0.0, truthRadiusPx = 0.0;  // when ballVisible
    BallCandidate chosen;           // the detected candidate
    FalsePositiveKind kind;
    FrameCrop crop;                 // BGR around the detection (cropAroundCircle)
};

// One missed ball frame as the listing shows it (omnitune-eval --miss-list), recorded only when
// QualityRunOptions::recordMisses: the ball's truth, why it was missed, and the candidate at the
// ball that got farthest through validation (when there was one), with the pixels around the ball.
struct MissedFrame {
    int frame = 0;  // index in its cell
    double truthPx = 0.0, truthPy = 0.0, truthRadiusPx = 0.0;
    double truthRangeM = 0.0;  // horizontal distance from the robot
    MissCause cause = MissCause::NoCandidate;
    bool radiusOff = false;         // the candidate's expected radius is off the true one
    bool hasCandidate = false;
    BallCandidate atBall;           // when hasCandidate
    // atBall is a prefilter refusal (core/PrefilterRefusals.h): its colour scores are the class
    // shares at the Hough maximum, and validation never saw it.
    bool atBallPrefiltered = false;
    bool detected = false;          // something else was detected in the frame
    BallCandidate chosen;           // when detected
    FrameCrop crop;                 // BGR around the ball (cropAroundCircle)
};

// Ball frames: found, missed and why (a variant's all, or one place's: calib/eval/BallPlace.h).
struct BallFrameTally {
    int withBall = 0;  // frames where the ball is visible
    int correct = 0;   // of them, found within the evaluation's max error
    // Why each missed ball frame was missed (indexed by MissCause), and how many of those misses
    // had a candidate at the ball whose expected radius was off the true one by more than the
    // circle fit allows.
    std::array<int, kMissCauseCount> missCauses{};
    int missesRadiusOff = 0;
    // Of the misses, how many had a candidate at the ball that the search's prefilter refused
    // (core/PrefilterRefusals.h): validation never judged it, whatever test the cause names.
    // Counted from the listed refusals: complete only with explainRejections (--misses).
    int missesPrefiltered = 0;

    void add(const BallFrameTally& other);
    double detectionPct() const;  // correct / withBall; 0 without ball frames
};

// What one variant did on a set of frames. Its ball frames' counts (BallFrameTally: frames where
// the ball is visible, found within the evaluation's max error, misses) are those of all of them.
struct QualityTally : BallFrameTally {
    int frames = 0;          // judged frames (ball or not)
    int falsePositives = 0;  // detections in ball-free frames or too far from the truth
    int atHiddenBalls = 0;   // detections of a ball more than half hidden, at it (not counted either way)
    // Correct detections of balls within QualityRunOptions::rangeWithinM: detected minus true
    // horizontal distance from the robot, m.
    std::vector<double> rangeErrorsM;
    std::vector<double> timesMs;  // whole pipeline per frame
    // The ball frames again, by where the ball lay (a frame counts in its range band, and in
    // OutOfPlay too when it is that).
    std::array<BallFrameTally, kBallPlaceCount> byPlace{};
    // What each false positive hit (indexed by falsePositiveKindIndex).
    std::array<int, kFalsePositiveKindCount> falsePositiveKinds{};
    // Each false positive of a cell's tally; add() leaves them out (totals count, cells list).
    std::vector<FalsePositiveFrame> falsePositiveFrames;
    // Each missed ball frame of a cell's tally when QualityRunOptions::recordMisses; add() leaves
    // them out.
    std::vector<MissedFrame> missedFrames;

    void add(const QualityTally& other);
    double falsePositivePct() const;  // falsePositives / frames
    double rangeBiasCm() const;       // mean of rangeErrorsM; 0 when empty
    double rangeStdCm() const;        // population std of rangeErrorsM; 0 when empty
    double timePercentileMs(double p) const;  // nearest rank, p in 0..100; 0 when empty
};

struct QualityCellResult {
    OpticsCell cell;
    std::string name;                 // opticsCellName(cell)
    std::vector<QualityTally> tallies;  // one per variant, in QualityRun::variants order
};

struct QualityRunOptions {
    EvaluationOptions evaluation;  // max error before a detection counts as a false positive
    double rangeWithinM = 4.0;     // range error is measured on balls this close (issue 9: 4 m)
    // Cells run on this many threads (each with its own pipelines); 0: one per hardware thread.
    // Detection and false-positive figures do not depend on it; per-frame times do (threads
    // share the cores and caches): 1 for timings worth quoting.
    int threads = 1;
    // Colours as a team sets them at the venue: Colours > Auto colours (calib/colour/AutoColour)
    // on this many frames of the cell's field and light, rendered with another seed than the
    // judged frames (no truth is used), replace the fitted config's default colours. 0: the
    // default colours (the matrix as the gate runs it).
    int autoColourFrames = 0;
    // Keep a MissedFrame (with its crop) for every missed ball frame (omnitune-eval --miss-list).
    // Its pipelines then also score what they reject (Pipeline::setExplainRejections) and list
    // every prefilter refusal, so each miss shows the scores of the candidate at the ball;
    // per-frame times are the robot's only without it.
    bool recordMisses = false;
    // Score what the pipelines reject (setExplainRejections) and list every prefilter refusal
    // (setListEveryRefusal) without keeping each miss; recordMisses does both too. The --misses
    // table then names what refused a ball that the listing's cap hid (as "no candidate").
    // Verdicts are the same; times are not the robot's.
    bool explainRejections = false;
    // The format the detector reads the rendered frames in: Uyvy hands it each frame as an IIDC
    // camera's YUV 4:2:2 (calib/sim/UyvyEncoding.h; the thesis' camera and the robot's path), so
    // the UYVY code (segmentation, denoise) is what is measured. Crops stay the rendered BGR.
    PixelFormat pixelFormat = PixelFormat::Bgr8;
};

struct QualityRun {
    std::vector<QualityVariant> variants;
    std::vector<QualityCellResult> cells;
    double renderMs = 0.0;  // time spent rendering and calibrating, summed over threads
};

// Throws std::invalid_argument when a variant's override does not apply, or the pipeline
// refuses a fitted config (the message names the cell). `progress` may be null; it is called
// from one thread at a time, and cancelling stops before the next cell (the run then holds
// the cells finished so far, in matrix order).
QualityRun runQuality(const std::vector<OpticsCell>& cells, const std::vector<QualityVariant>& variants,
                      const Config& base = {}, const QualityRunOptions& options = {}, Progress* progress = nullptr);

// One variant summed over the cells `filter` accepts (all when empty).
QualityTally qualityTotal(const QualityRun& run, std::size_t variant,
                          const std::function<bool(const OpticsCell&)>& filter = {});

// The ball cell where the variant found the smallest share of balls (first in matrix order on
// ties); nullptr when no cell has a ball.
const QualityCellResult* worstQualityCell(const QualityRun& run, std::size_t variant);

}  // namespace omnitune
