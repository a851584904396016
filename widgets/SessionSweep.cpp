#include "widgets/SessionSweep.h"

#include "core/Progress.h"

#include <QElapsedTimer>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

// core's progress-and-cancel interface on top of the sweep's flag and its progress signal:
// calib reports percents, the window shows frames (the result knows the total by then).
class SweepProgress : public Progress {
public:
    SweepProgress(SessionSweep& sweep, const ConfigComparisonResult& result) : sweep_(sweep), result_(result) {}
    void update(double percent) override
    {
        const int total = result_.total;
        emit sweep_.progress(int(std::lround(percent * std::max(total, 0) / 100.0)), total);
    }
    bool isCancelRequested() const override { return sweep_.isCancelRequested(); }

private:
    SessionSweep& sweep_;
    const ConfigComparisonResult& result_;
};

}  // namespace

QVector<FrameMark> sweepMarks(const SweepResult& result)
{
    QVector<FrameMark> marks;
    for (const FrameOutcome& o : result.current)
        if (o.processed && o.detection.found) marks.push_back({o.frame, FrameMarkKind::Detected});
    for (const FrameComparison& c : result.comparison.frames) {
        switch (c.change) {
        case FrameChange::Same: break;
        case FrameChange::Appeared: marks.push_back({c.frame, FrameMarkKind::Appeared}); break;
        case FrameChange::Vanished: marks.push_back({c.frame, FrameMarkKind::Vanished}); break;
        case FrameChange::Moved: marks.push_back({c.frame, FrameMarkKind::Moved}); break;
        }
    }
    return marks;
}

const QVector<FrameMarkKind>& sweepMarkKinds()
{
    static const QVector<FrameMarkKind> kinds = {FrameMarkKind::Detected, FrameMarkKind::Appeared,
                                                 FrameMarkKind::Vanished, FrameMarkKind::Moved};
    return kinds;
}

SessionSweep::SessionSweep(SweepRequest request, QObject* parent) : QObject(parent), request_(std::move(request))
{
    // A Config copy shares the mask's pixels with the window's; the thread gets its own.
    request_.current.mask = request_.current.mask.clone();
    qRegisterMetaType<std::shared_ptr<const omnitune::SweepResult>>();
}

SessionSweep::~SessionSweep()
{
    cancel();
    if (thread_) thread_->wait();
}

void SessionSweep::start()
{
    Q_ASSERT(!thread_);
    thread_.reset(QThread::create([this] { run(); }));
    thread_->setObjectName("session sweep");
    thread_->start(QThread::LowPriority);  // the window's own pipeline and painting come first
}

void SessionSweep::cancel() { cancel_.store(true); }

bool SessionSweep::isRunning() const { return thread_ && thread_->isRunning(); }

void SessionSweep::run()
{
    ConfigComparisonRequest request;
    request.sourcePath = request_.sourcePath.toStdString();
    request.current = request_.current;
    request.savedConfigPath = request_.savedConfigPath.toStdString();
    request.truth = request_.truth;
    request.comparison = request_.comparison;
    request.evaluation = request_.evaluation;

    auto result = std::make_shared<SweepResult>();
    result->sourcePath = request_.sourcePath;
    result->savedConfigPath = request_.savedConfigPath;
    QElapsedTimer clock;
    clock.start();
    SweepProgress progressAdapter(*this, *result);
    ConfigComparisonResult& run = *result;
    runConfigComparison(request, run, &progressAdapter);
    result->elapsedS = clock.elapsed() / 1000.0;
    emit finished(result);
}

}  // namespace omnitune
