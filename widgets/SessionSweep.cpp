#include "widgets/SessionSweep.h"

#include "calib/eval/BatchRun.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"
#include "calib/source/FrameSourceFactory.h"
#include "core/Pipeline.h"
#include "core/Progress.h"

#include <QElapsedTimer>
#include <QThread>

#include <cmath>
#include <functional>

namespace omnitune {

namespace {

// core's progress-and-cancel interface on top of the sweep's flag and its progress signal.
class SweepProgress : public Progress {
public:
    SweepProgress(const std::atomic<bool>& cancel, std::function<void(double)> onUpdate)
        : cancel_(cancel), onUpdate_(std::move(onUpdate))
    {
    }
    void update(double percent) override { onUpdate_(percent); }
    bool isCancelRequested() const override { return cancel_.load(); }

private:
    const std::atomic<bool>& cancel_;
    std::function<void(double)> onUpdate_;
};

// Same file contents and the same mask: running it again would only repeat the same numbers.
bool sameDetector(const Config& a, const Config& b)
{
    if (serializeConfig(a) != serializeConfig(b)) return false;
    if (a.mask.empty() || b.mask.empty()) return a.mask.empty() == b.mask.empty();
    return a.mask.size() == b.mask.size() && a.mask.type() == b.mask.type() && cv::norm(a.mask, b.mask, cv::NORM_INF) == 0;
}

// The saved config's pipeline, or why there is none.
struct SavedPipeline {
    std::unique_ptr<Pipeline> pipeline;
    bool sameAsCurrent = false;
    QString note;
};

SavedPipeline makeSavedPipeline(const QString& path, const Config& current)
{
    SavedPipeline saved;
    if (path.isEmpty()) {
        saved.note = QObject::tr("The config has never been saved: there is nothing to compare with, the slider "
                                 "marks detections only.");
        return saved;
    }
    const ConfigLoad load = loadConfig(path.toStdString());
    if (!load.ok()) {
        saved.note = QObject::tr("The saved config cannot be loaded, so nothing is compared: %1")
                         .arg(QString::fromStdString(load.error->toString()));
        return saved;
    }
    if (sameDetector(load.config, current)) {
        saved.sameAsCurrent = true;
        return saved;
    }
    try {
        saved.pipeline = std::make_unique<Pipeline>(load.config);
    } catch (const std::exception& e) {
        saved.note = QObject::tr("The saved config %1 cannot run, so nothing is compared: %2").arg(path, e.what());
    }
    return saved;
}

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
    auto result = std::make_shared<SweepResult>();
    QElapsedTimer clock;
    clock.start();
    try {
        sweep(*result);
    } catch (const std::exception& e) {  // nothing escapes the thread: it becomes the message
        result->error = tr("The sweep stopped: %1").arg(e.what());
    }
    result->elapsedS = clock.elapsed() / 1000.0;
    emit finished(result);
}

void SessionSweep::sweep(SweepResult& result)
{
    result.sourcePath = request_.sourcePath;
    result.savedConfigPath = request_.savedConfigPath;
    result.hasTruth = !request_.truth.empty();
    SourceOpen<FrameSource> opened = openFrameSource(request_.sourcePath.toStdString());
    if (!opened.ok()) {
        result.error = QString::fromStdString(opened.error);
        return;
    }
    FrameSource& source = *opened.source;
    std::unique_ptr<Pipeline> current;
    try {
        current = std::make_unique<Pipeline>(request_.current);
    } catch (const std::exception& e) {
        result.error = tr("The current config cannot run: %1").arg(e.what());
        return;
    }
    SavedPipeline saved = makeSavedPipeline(request_.savedConfigPath, request_.current);
    result.savedIsCurrent = saved.sameAsCurrent;
    result.hasSaved = saved.sameAsCurrent || saved.pipeline;
    result.savedNote = saved.note;

    result.total = source.frameCount();
    emit progress(0, result.total);
    SweepProgress progressAdapter(cancel_, [&](double percent) {
        emit progress(int(std::lround(percent * result.total / 100.0)), result.total);
    });
    PipelineResult savedRun;
    const BatchSummary summary = runBatch(
        source, *current,
        [&](int index, const Frame* frame, const PipelineResult& r) {
            result.current.push_back(outcomeOf(index, r));
            if (!r.ok() && result.firstFrameError.isEmpty())
                result.firstFrameError = tr("frame %1: %2").arg(index).arg(QString::fromStdString(r.error));
            if (!saved.pipeline) return;
            if (!frame) {
                result.saved.push_back(outcomeOf(index, r));  // unreadable for both
                return;
            }
            try {
                saved.pipeline->process(frame->image, frame->format, savedRun, false);
            } catch (const std::exception& e) {
                savedRun = PipelineResult{};
                savedRun.error = e.what();
            }
            result.saved.push_back(outcomeOf(index, savedRun));
        },
        &progressAdapter);
    result.visited = summary.frames;
    result.cancelled = summary.cancelled;
    if (saved.sameAsCurrent) result.saved = result.current;

    result.currentRow = evaluate(result.current, request_.truth, request_.evaluation);
    for (const FrameOutcome& o : result.current) {
        const auto t = request_.truth.find(o.frame);
        const TruthVerdict v = judge(o, t == request_.truth.end() ? nullptr : &t->second, request_.evaluation);
        if (v == TruthVerdict::FalsePositive) result.falsePositiveFrames.push_back(o.frame);
        if (v == TruthVerdict::Missed) result.missedFrames.push_back(o.frame);
    }
    if (result.hasSaved) {
        result.savedRow = evaluate(result.saved, request_.truth, request_.evaluation);
        result.comparison = compareSessions(result.current, result.saved, request_.comparison);
    }
}

}  // namespace omnitune
