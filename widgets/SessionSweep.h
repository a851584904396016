#pragma once
// "Apply to whole session": re-runs the config being tuned, and the saved one beside it, over
// every frame of the source in a thread of its own, and reports detection ratio, false
// positives (with truth), timing and what changed frame by frame. It opens its own
// FrameSource (sources are single-threaded and the window holds one), reads each frame once
// and runs both pipelines on it, so a cancelled sweep still compares the same frames.
#include "core/Config.h"
#include "calib/eval/Evaluation.h"
#include "widgets/FrameMark.h"
#include "calib/eval/SessionComparison.h"
#include "calib/session/TruthCsv.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <map>
#include <memory>
#include <vector>

class QThread;

namespace omnitune {

struct SweepRequest {
    QString sourcePath;               // session folder, video, image folder or glob
    Config current;                   // the config being tuned (the document's)
    QString savedConfigPath;          // the document's file; empty: nothing saved to compare with
    std::map<int, TruthRow> truth;    // ground truth by frame; may be empty
    ComparisonOptions comparison;
    EvaluationOptions evaluation;
};

struct SweepResult {
    QString sourcePath;
    QString savedConfigPath;   // the file the saved column comes from
    QString error;             // nothing ran (the source or the current config is unusable)
    int total = 0;             // frames in the source; -1 when the source does not know
    int visited = 0;           // frames visited (all of them unless cancelled)
    bool cancelled = false;    // stopped early: everything below covers the visited frames
    QString firstFrameError;   // the first frame that could not be read or processed, if any
    double elapsedS = 0.0;     // wall time of the sweep

    bool hasSaved = false;        // the saved config ran: `saved`, `savedRow`, `comparison` valid
    bool savedIsCurrent = false;  // the saved file holds the same config (ran once, used twice)
    QString savedNote;            // why there is no comparison, when hasSaved is false
    bool hasTruth = false;        // truth rows were given: ratios and false positives mean something

    std::vector<FrameOutcome> current;
    std::vector<FrameOutcome> saved;
    EvaluationRow currentRow;
    std::vector<int> falsePositiveFrames;  // the current config's, with truth (judge())
    std::vector<int> missedFrames;
    EvaluationRow savedRow;
    SessionComparison comparison;

    bool ok() const { return error.isEmpty(); }
};

// The slider marks of a result: Detected where the current config found a ball, and each
// changed frame with its kind. These are the kinds a sweep owns (sweepMarkKinds()).
QVector<FrameMark> sweepMarks(const SweepResult& result);
const QVector<FrameMarkKind>& sweepMarkKinds();

class SessionSweep : public QObject {
    Q_OBJECT
public:
    explicit SessionSweep(SweepRequest request, QObject* parent = nullptr);
    ~SessionSweep() override;  // cancels and waits for the thread

    void start();   // once
    void cancel();  // from any thread; the sweep stops before its next frame
    bool isCancelRequested() const { return cancel_.load(); }
    bool isRunning() const;

signals:
    // Both are emitted from the sweep's thread: connect with a receiver living in the GUI
    // thread (queued), or Qt::DirectConnection for something thread-safe such as cancel().
    void progress(int done, int total);  // total -1: unknown length
    void finished(std::shared_ptr<const omnitune::SweepResult> result);

private:
    void run();  // the sweep thread
    void sweep(SweepResult& result);

    SweepRequest request_;
    std::atomic<bool> cancel_{false};
    std::unique_ptr<QThread> thread_;
};

}  // namespace omnitune

Q_DECLARE_METATYPE(std::shared_ptr<const omnitune::SweepResult>)
