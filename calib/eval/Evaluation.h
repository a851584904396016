#pragma once
// The thesis' evaluation (ch. 5, Tables 5.1-5.4) of detections against a session's truth:
// real position, mean and std of the detected position, detection ratio; plus false
// positives, position error and processing time. Pure: outcomes and truth in, a row out.
#include "core/PipelineResult.h"
#include "calib/session/TruthCsv.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct FrameOutcome {
    int frame = 0;
    bool processed = false;  // false: the frame could not be read or processed
    BallDetection detection;
    double timeMs = 0.0;
};

// What evaluate() needs of one pipeline result.
FrameOutcome outcomeOf(int frame, const PipelineResult& result);
// Processed frames with a detection, truth or not.
int detectionCount(const std::vector<FrameOutcome>& outcomes);

struct EvaluationOptions {
    double maxErrorM = 0.5;  // a detection farther than this from the truth is a false positive
};

struct EvaluationRow {
    std::string session;
    std::string algorithm;
    int frames = 0;          // frames processed
    int failed = 0;          // frames that could not be read or processed (count as misses)
    int annotated = 0;       // processed frames with a truth row
    int withBall = 0;        // annotated frames where the ball is visible
    int correct = 0;         // ball frames with a detection within maxErrorM of the truth
    int falsePositives = 0;  // detections in ball-less frames or farther than maxErrorM
    double detectionRatioPct = 0.0;  // correct / withBall
    double falsePositivePct = 0.0;   // falsePositives / annotated
    // Field-frame positions (m), when the truth carries the robot pose: the ball's real
    // position and the mean and std of every detection in ball frames (thesis Tables 5.1-5.3).
    bool hasFieldPositions = false;  // real position known (the truth has robot poses)
    bool hasDetections = false;      // at least one detection in a ball frame (mean/std valid)
    double realX = 0, realY = 0, meanX = 0, meanY = 0, stdX = 0, stdY = 0;
    double meanErrorM = 0.0;  // over ball frames with a detection (robot frame, outliers included)
    double maxErrorM = 0.0;
    double timeMinMs = 0.0, timeAvgMs = 0.0, timeMaxMs = 0.0;
};

EvaluationRow evaluate(const std::vector<FrameOutcome>& outcomes, const std::map<int, TruthRow>& truth,
                       const EvaluationOptions& options = {});

// One frame against its truth, as evaluate() counts it.
enum class TruthVerdict {
    Unannotated,    // no truth row for the frame
    Correct,        // ball visible and found within maxErrorM, or no ball and none found
    Missed,         // ball visible, nothing found (or the frame could not be processed)
    FalsePositive,  // a detection in a ball-less frame, or farther than maxErrorM from the truth
    AtHiddenBall,   // no visible ball, but the detection lies within maxErrorM of one more than
                    // half hidden (behind a rod, a robot, our body; cut by the frame): neither
                    // a find nor a false positive
};
// `hiddenBallM`: where (robot frame, m) the frame's ball lies when it is in the image but more
// than half hidden, so not `truth->ballVisible`; a simulator knows it, truth.csv does not say.
TruthVerdict judge(const FrameOutcome& outcome, const TruthRow* truth, const EvaluationOptions& options = {},
                   const std::optional<cv::Point2d>& hiddenBallM = std::nullopt);

std::string evaluationMarkdown(const std::vector<EvaluationRow>& rows);
std::string evaluationCsv(const std::vector<EvaluationRow>& rows);

}  // namespace omnitune
