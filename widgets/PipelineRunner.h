#pragma once
// Runs the pipeline off the GUI thread. Requests replace each other: while one frame is being
// processed only the newest request waits, so dragging a slider never queues stale work and
// the window never blocks on the detector.
#include "Config.h"
#include "PipelineResult.h"
#include "PixelFormat.h"

#include <QObject>
#include <QThread>

#include <memory>

namespace omnitune {

struct PipelineRun {
    int frameIndex = -1;
    cv::Mat frame;            // the frame that was processed (BGR or UYVY)
    PixelFormat format = PixelFormat::Bgr8;
    Config config;            // the config this run used (overlays and the inspector use it)
    PipelineResult result;    // with the five stage images
    QString error;            // the config could not be used (result then empty)
};

class PipelineWorker;

class PipelineRunner : public QObject {
    Q_OBJECT
public:
    explicit PipelineRunner(QObject* parent = nullptr);
    ~PipelineRunner() override;

    // `configGeneration` changes whenever the config does; the worker rebuilds its pipeline
    // (LUT, tables) only then.
    void request(int frameIndex, const cv::Mat& frame, PixelFormat format, const Config& config, quint64 configGeneration);
    bool isBusy() const;

signals:
    void finished(std::shared_ptr<const omnitune::PipelineRun> run);

private:
    QThread thread_;
    PipelineWorker* worker_;
};

}  // namespace omnitune

Q_DECLARE_METATYPE(std::shared_ptr<const omnitune::PipelineRun>)
