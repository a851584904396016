#include "widgets/PipelineRunner.h"

#include "core/Pipeline.h"
#include "widgets/MaskTint.h"

#include <QMutex>

#include <optional>

namespace omnitune {

namespace {
struct Request {
    std::shared_ptr<FrameSource> source;
    quint64 sourceTag;
    int frameIndex;
    Config config;
    quint64 generation;
};
}  // namespace

class PipelineWorker : public QObject {
    Q_OBJECT
public:
    // Called from the GUI thread: keeps only the newest request and wakes the worker once.
    void post(Request r)
    {
        QMutexLocker lock(&mutex_);
        const bool wake = !pending_ && !running_;
        pending_ = std::move(r);
        if (wake) QMetaObject::invokeMethod(this, &PipelineWorker::drain, Qt::QueuedConnection);
    }
    bool busy() const
    {
        QMutexLocker lock(&mutex_);
        return running_ || pending_.has_value();
    }

signals:
    void finished(std::shared_ptr<const omnitune::PipelineRun> run);

private:
    void drain()
    {
        for (;;) {
            std::optional<Request> r;
            {
                QMutexLocker lock(&mutex_);
                if (!pending_) {
                    running_ = false;
                    return;
                }
                r = std::move(pending_);
                pending_.reset();
                running_ = true;
            }
            emit finished(process(*r));
        }
    }

    std::shared_ptr<const PipelineRun> process(const Request& r)
    {
        auto run = std::make_shared<PipelineRun>();
        run->sourceTag = r.sourceTag;
        run->frameIndex = r.frameIndex;
        run->config = r.config;
        // Changing only the config re-runs the frame already decoded.
        if (r.source != source_ || r.frameIndex != frame_.index || frame_.image.empty()) {
            source_ = r.source;
            frame_ = Frame();
            if (const auto err = source_->read(r.frameIndex, frame_)) {
                frame_ = Frame();
                run->error = QString::fromStdString(err->toString());
                run->frameUnreadable = true;
                return run;
            }
            frame_.index = r.frameIndex;
        }
        run->frame = frame_.image;
        run->format = frame_.format;
        try {
            if (!pipeline_ || generation_ != r.generation) {
                pipeline_.reset();  // a config that cannot be built leaves no stale pipeline
                outline_ = std::make_shared<const Polylines>(maskOutline(r.config.mask));
                tint_ = maskTint(r.config.mask);
                pipeline_ = std::make_unique<Pipeline>(r.config);
                pipeline_->setExplainRejections(true);  // the candidate table explains every verdict
                generation_ = r.generation;
            }
            run->maskOutline = outline_;
            run->maskTint = tint_;
            pipeline_->process(frame_.image, frame_.format, run->result, true);
        } catch (const std::exception& e) {
            run->error = QString::fromStdString(e.what());  // the pipeline itself stays usable
        }
        return run;
    }

    mutable QMutex mutex_;
    std::optional<Request> pending_;
    bool running_ = false;
    // Worker thread only:
    std::unique_ptr<Pipeline> pipeline_;
    quint64 generation_ = 0;
    std::shared_ptr<const Polylines> outline_;
    std::shared_ptr<const QImage> tint_;
    std::shared_ptr<FrameSource> source_;
    Frame frame_;  // the last frame decoded from source_
};

PipelineRunner::PipelineRunner(QObject* parent) : QObject(parent), worker_(new PipelineWorker)
{
    qRegisterMetaType<std::shared_ptr<const omnitune::PipelineRun>>();
    worker_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    connect(worker_, &PipelineWorker::finished, this, &PipelineRunner::finished, Qt::QueuedConnection);
    thread_.setObjectName("pipeline");
    thread_.start();
}

PipelineRunner::~PipelineRunner()
{
    thread_.quit();
    thread_.wait();
}

void PipelineRunner::request(std::shared_ptr<FrameSource> source, quint64 sourceTag, int frameIndex,
                             const Config& config, quint64 configGeneration)
{
    worker_->post({std::move(source), sourceTag, frameIndex, config, configGeneration});
}

bool PipelineRunner::isBusy() const { return worker_->busy(); }

}  // namespace omnitune

#include "PipelineRunner.moc"
