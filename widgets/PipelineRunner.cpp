#include "PipelineRunner.h"

#include "Pipeline.h"

#include <QMutex>

#include <optional>

namespace omnitune {

namespace {
struct Request {
    int frameIndex;
    cv::Mat frame;
    PixelFormat format;
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
            auto run = std::make_shared<PipelineRun>();
            run->frameIndex = r->frameIndex;
            run->frame = r->frame;
            run->format = r->format;
            run->config = r->config;
            try {
                if (!pipeline_ || generation_ != r->generation) {
                    pipeline_.reset();  // a config that cannot be built leaves no stale pipeline
                    pipeline_ = std::make_unique<Pipeline>(r->config);
                    generation_ = r->generation;
                }
                pipeline_->process(r->frame, r->format, run->result, true);
            } catch (const std::exception& e) {
                run->error = QString::fromStdString(e.what());  // the pipeline itself stays usable
            }
            emit finished(run);
        }
    }

    mutable QMutex mutex_;
    std::optional<Request> pending_;
    bool running_ = false;
    std::unique_ptr<Pipeline> pipeline_;  // worker thread only
    quint64 generation_ = 0;
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

void PipelineRunner::request(int frameIndex, const cv::Mat& frame, PixelFormat format, const Config& config,
                             quint64 configGeneration)
{
    worker_->post({frameIndex, frame.clone(), format, config, configGeneration});
}

bool PipelineRunner::isBusy() const { return worker_->busy(); }

}  // namespace omnitune

#include "PipelineRunner.moc"
