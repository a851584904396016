#include "calib/eval/Evaluation.h"

#include "calib/eval/DetectionCsv.h"
#include "calib/sim/RobotPose.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace omnitune {

FrameOutcome outcomeOf(int frame, const PipelineResult& result)
{
    return {frame, result.ok(), result.detection, result.timings.totalMs};
}

int detectionCount(const std::vector<FrameOutcome>& outcomes)
{
    return int(std::count_if(outcomes.begin(), outcomes.end(),
                             [](const FrameOutcome& o) { return o.processed && o.detection.found; }));
}

namespace {

struct Moments {
    int n = 0;
    double sx = 0, sy = 0, sxx = 0, syy = 0;
    void add(double x, double y)
    {
        ++n;
        sx += x;
        sy += y;
        sxx += x * x;
        syy += y * y;
    }
    double meanX() const { return n ? sx / n : 0; }
    double meanY() const { return n ? sy / n : 0; }
    double stdX() const { return n ? std::sqrt(std::max(0.0, sxx / n - meanX() * meanX())) : 0; }
    double stdY() const { return n ? std::sqrt(std::max(0.0, syy / n - meanY() * meanY())) : 0; }
};

std::string fmt(const char* f, double a, double b)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, f, a, b);
    return buf;
}

}  // namespace

TruthVerdict judge(const FrameOutcome& o, const TruthRow* truth, const EvaluationOptions& options,
                   const std::optional<cv::Point2d>& hiddenBallM)
{
    if (!truth) return TruthVerdict::Unannotated;
    const BallDetection& d = o.detection;
    if (!o.processed) return truth->ballVisible ? TruthVerdict::Missed : TruthVerdict::Correct;
    if (!truth->ballVisible) {
        if (!d.found) return TruthVerdict::Correct;
        const bool atHidden =
            hiddenBallM && std::hypot(d.xM - hiddenBallM->x, d.yM - hiddenBallM->y) <= options.maxErrorM;
        return atHidden ? TruthVerdict::AtHiddenBall : TruthVerdict::FalsePositive;
    }
    if (!d.found) return TruthVerdict::Missed;
    return std::hypot(d.xM - truth->xM, d.yM - truth->yM) <= options.maxErrorM ? TruthVerdict::Correct
                                                                               : TruthVerdict::FalsePositive;
}

EvaluationRow evaluate(const std::vector<FrameOutcome>& outcomes, const std::map<int, TruthRow>& truth,
                       const EvaluationOptions& options)
{
    EvaluationRow row;
    Moments real;
    Moments detected;
    double errorSum = 0;
    int errorCount = 0;
    bool allPoses = true;
    double timeSum = 0;
    row.timeMinMs = std::numeric_limits<double>::infinity();
    for (const FrameOutcome& o : outcomes) {
        if (!o.processed) {
            ++row.failed;
            // An unreadable frame with the ball is a miss, not a frame left out of the ratio.
            const auto t = truth.find(o.frame);
            if (t != truth.end() && t->second.ballVisible) ++row.withBall;
            continue;
        }
        ++row.frames;
        timeSum += o.timeMs;
        row.timeMinMs = std::min(row.timeMinMs, o.timeMs);
        row.timeMaxMs = std::max(row.timeMaxMs, o.timeMs);
        const auto t = truth.find(o.frame);
        if (t == truth.end()) continue;
        ++row.annotated;
        const TruthRow& tr = t->second;
        const BallDetection& d = o.detection;
        const TruthVerdict verdict = judge(o, &tr, options);
        if (!tr.ballVisible) {
            row.falsePositives += verdict == TruthVerdict::FalsePositive;
            continue;
        }
        ++row.withBall;
        allPoses = allPoses && tr.robot.has_value();
        if (tr.robot) {
            const cv::Point2d p = toFieldFrame(*tr.robot, {tr.xM, tr.yM});
            real.add(p.x, p.y);
        }
        if (!d.found) continue;
        const double err = std::hypot(d.xM - tr.xM, d.yM - tr.yM);
        errorSum += err;
        ++errorCount;
        row.maxErrorM = std::max(row.maxErrorM, err);
        ++(verdict == TruthVerdict::Correct ? row.correct : row.falsePositives);
        if (tr.robot) {
            const cv::Point2d p = toFieldFrame(*tr.robot, {d.xM, d.yM});
            detected.add(p.x, p.y);
        }
    }
    if (row.frames == 0) row.timeMinMs = 0;
    row.timeAvgMs = row.frames ? timeSum / row.frames : 0;
    row.detectionRatioPct = row.withBall ? 100.0 * row.correct / row.withBall : 0;
    row.falsePositivePct = row.annotated ? 100.0 * row.falsePositives / row.annotated : 0;
    row.meanErrorM = errorCount ? errorSum / errorCount : 0;
    row.hasFieldPositions = allPoses && real.n > 0;
    row.hasDetections = detected.n > 0;
    if (row.hasFieldPositions) {
        row.realX = real.meanX();
        row.realY = real.meanY();
        row.meanX = detected.meanX();
        row.meanY = detected.meanY();
        row.stdX = detected.stdX();
        row.stdY = detected.stdY();
    }
    return row;
}

std::string evaluationMarkdown(const std::vector<EvaluationRow>& rows)
{
    std::string md =
        "| session | algorithm | real position (m) | average (m) | std (m) | detection ratio (%) | false positives (%) "
        "| mean / max error (m) | time min / avg / max (ms) | frames (with ball) |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
    char buf[512];
    for (const EvaluationRow& r : rows) {
        const std::string real = r.hasFieldPositions ? fmt("(%.2f, %.2f)", r.realX, r.realY) : "n/a";
        const bool positions = r.hasFieldPositions && r.hasDetections;
        const std::string mean = positions ? fmt("(%.2f, %.2f)", r.meanX, r.meanY) : "n/a";
        const std::string sd = positions ? fmt("(%.2f, %.2f)", r.stdX, r.stdY) : "n/a";
        std::snprintf(buf, sizeof buf, "| %s | %s | %s | %s | %s | %.1f | %.1f | %.3f / %.3f | %.1f / %.1f / %.1f | %d (%d) |\n",
                      r.session.c_str(), r.algorithm.c_str(), real.c_str(), mean.c_str(), sd.c_str(),
                      r.detectionRatioPct, r.falsePositivePct, r.meanErrorM, r.maxErrorM, r.timeMinMs, r.timeAvgMs,
                      r.timeMaxMs, r.frames, r.withBall);
        md += buf;
    }
    return md;
}

std::string evaluationCsv(const std::vector<EvaluationRow>& rows)
{
    std::string csv =
        "session,algorithm,frames,annotated,with_ball,correct,false_positives,detection_ratio_pct,false_positive_pct,"
        "real_x_m,real_y_m,mean_x_m,mean_y_m,std_x_m,std_y_m,mean_error_m,max_error_m,time_min_ms,time_avg_ms,time_max_ms\n";
    char buf[512];
    for (const EvaluationRow& r : rows) {
        std::snprintf(buf, sizeof buf,
                      "%s,%s,%d,%d,%d,%d,%d,%.2f,%.2f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%.3f\n",
                      csvField(r.session).c_str(), r.algorithm.c_str(), r.frames, r.annotated, r.withBall, r.correct,
                      r.falsePositives, r.detectionRatioPct, r.falsePositivePct, r.realX, r.realY, r.meanX, r.meanY,
                      r.stdX, r.stdY, r.meanErrorM, r.maxErrorM, r.timeMinMs, r.timeAvgMs, r.timeMaxMs);
        csv += buf;
    }
    return csv;
}

}  // namespace omnitune
