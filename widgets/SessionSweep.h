#pragma once
// "Apply to whole session" off the GUI thread: runs calib's two-config comparison
// (calib/eval/ConfigComparisonRun.h: the config being tuned and the saved one over every frame)
// in a thread of its own and reports progress and the result as signals. It opens its own
// FrameSource (sources are single-threaded and the window holds one).
#include "calib/eval/ConfigComparisonRun.h"
#include "widgets/FrameMark.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

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

// calib's result plus what the window shows beside it.
struct SweepResult : ConfigComparisonResult {
    QString sourcePath;
    QString savedConfigPath;  // the file the saved column comes from
    double elapsedS = 0.0;    // wall time of the sweep
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

    SweepRequest request_;
    std::atomic<bool> cancel_{false};
    std::unique_ptr<QThread> thread_;
};

}  // namespace omnitune

Q_DECLARE_METATYPE(std::shared_ptr<const omnitune::SweepResult>)
