#pragma once
// Reads frames and runs the pipeline off the GUI thread. Requests replace each other: while one
// frame is being processed only the newest request waits, so dragging a slider never queues
// stale work and the window never blocks on decoding a frame or on the detector.
#include "core/Config.h"
#include "calib/source/FrameSource.h"
#include "calib/mask/MaskOutline.h"
#include "core/PipelineResult.h"
#include "core/PixelFormat.h"

#include <QImage>
#include <QObject>
#include <QThread>

#include <memory>

namespace omnitune {

struct PipelineRun {
    quint64 sourceTag = 0;    // the request's tag: tells runs of a source opened before apart
    int frameIndex = -1;
    cv::Mat frame;            // the frame that was processed (BGR or UYVY)
    PixelFormat format = PixelFormat::Bgr8;
    Config config;            // the config this run used (overlays and the inspector use it)
    std::shared_ptr<const Polylines> maskOutline;  // of config.mask; empty without a mask
    std::shared_ptr<const QImage> maskTint;        // config.mask's unprocessed pixels tinted; null without a mask
    PipelineResult result;    // with the five stage images
    QString error;            // the frame could not be read or the config used (result then empty)
    bool frameUnreadable = false;  // `error` is about the frame, not the config
};

class PipelineWorker;

class PipelineRunner : public QObject {
    Q_OBJECT
public:
    explicit PipelineRunner(QObject* parent = nullptr);
    ~PipelineRunner() override;

    // Frame `frameIndex` of `source`, read on the worker thread: from this call on, the source
    // belongs to the worker (FrameSource is single-threaded); the window keeps only the
    // pointer to pass back. `configGeneration` changes whenever the config does; the worker
    // rebuilds its pipeline (LUT, tables) only then.
    // `sourceTag` comes back in the run, so runs still in flight when another source is
    // opened can be told apart and dropped.
    void request(std::shared_ptr<FrameSource> source, quint64 sourceTag, int frameIndex, const Config& config,
                 quint64 configGeneration);
    bool isBusy() const;

signals:
    void finished(std::shared_ptr<const omnitune::PipelineRun> run);

private:
    QThread thread_;
    PipelineWorker* worker_;
};

}  // namespace omnitune

Q_DECLARE_METATYPE(std::shared_ptr<const omnitune::PipelineRun>)
