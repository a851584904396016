#include "widgets/LiveController.h"

#include "calib/camera/CameraFrameSource.h"
#include "calib/camera/CameraSettingsIo.h"
#include "calib/camera/ReplaySource.h"
#include "calib/camera/SimulatedCamera.h"
#include "calib/fit/MeasuredCalibration.h"
#include "core/Geometry.h"
#include "widgets/CameraPanel.h"
#include "widgets/CameraSourceMenu.h"
#include "widgets/ConfigDocument.h"
#include "widgets/FrameNavigator.h"
#include "widgets/PipelineRunner.h"
#include "widgets/RecordBar.h"

#include <QAction>
#include <QFileDialog>
#include <QLabel>
#include <QMenu>
#include <QTimer>

#include <cmath>

namespace omnitune {

LiveController::LiveController(ConfigDocument* doc, FrameNavigator* nav, PipelineRunner* runner,
                               CameraPanel* cameraPanel, QWidget* window)
    : QObject(window), doc_(doc), nav_(nav), runner_(runner), cameraPanel_(cameraPanel), window_(window),
      statusLabel_(new QLabel(window)), recordBar_(new RecordBar(window))
{
    statusLabel_->setObjectName("liveStatus");
    statusLabel_->hide();
    clock_.start();
    connect(nav_, &FrameNavigator::playingChanged, this, &LiveController::onPlayingChanged);
    connect(doc_, &ConfigDocument::changed, this, &LiveController::configChanged);
    connect(runner_, &PipelineRunner::finished, this, &LiveController::onRunFinished);
    connect(recordBar_, &RecordBar::stopRequested, this, &LiveController::stopRecording);
    connect(recordBar_, &RecordBar::stoppedByItself, this, &LiveController::stopRecording);
    reconnect_ = new QAction(tr("&Reconnect camera"), this);
    reconnect_->setObjectName("cameraReconnect");
    connect(reconnect_, &QAction::triggered, this, &LiveController::reconnect);
    record_ = new QAction(tr("&Record to a new session folder..."), this);
    record_->setObjectName("cameraRecord");
    record_->setStatusTip(tr("Write the live frames into a session folder, with the camera settings in session.yml"));
    connect(record_, &QAction::triggered, this, &LiveController::chooseRecordingFolder);
    stopRecord_ = new QAction(tr("S&top recording"), this);
    stopRecord_->setObjectName("cameraStopRecording");
    connect(stopRecord_, &QAction::triggered, this, &LiveController::stopRecording);
    connect(&grabTimer_, &QTimer::timeout, this, &LiveController::grabTick);
    useFitted_ = new QAction(tr("Use the simulated camera's fitted config"), this);
    useFitted_->setObjectName("cameraUseFittedConfig");
    useFitted_->setToolTip(tr("Centre, radii, mask, distance map and ball model fitted to the simulated camera's optics "
                              "(colours and thresholds stay); one undo step"));
    connect(useFitted_, &QAction::triggered, this, &LiveController::useFittedConfig);
    if (cameraPanel_) {
        cameraPanel_->setGrabber([this](Frame& frame) { return grabLive(frame); });
        connect(cameraPanel_, &CameraPanel::calibrationStarted, this, [this] {
            if (camera_ && !failed_ && !nav_->isPlaying()) nav_->togglePlay();  // watch it converge, live
        });
    }
    updateActions();
}

LiveController::~LiveController()
{
    // The window calls close() while its widgets exist; here only what needs none of them.
    recorder_.reset();  // finishes the session
    if (cameraPanel_) cameraPanel_->setGrabber({});  // it grabbed through this
    if (!camera_) return;
    if (cameraPanel_) cameraPanel_->setCamera(nullptr);
    camera_->camera().stop();
    camera_->camera().close();
}

void LiveController::fillMenu(QMenu* camera)
{
    auto* sources = new CameraSourceMenu(camera->addMenu(tr("Live &source")), this);
    connect(sources, &CameraSourceMenu::chosen, this, &LiveController::onSourceChosen);
    camera->addAction(record_);
    camera->addAction(stopRecord_);
    camera->addAction(reconnect_);
}

void LiveController::onSourceChosen(const QString& source, SimulatedStart start)
{
    // The camera already live chosen again: keep its handle (a real device refuses a second
    // one as busy) and apply the config's settings again, as opening it would.
    if (camera_ && !failed_ && liveSource_ && *liveSource_ == std::make_pair(source, start)) {
        QStringList notes;
        if (applySettings_) applySettings(notes);
        if (cameraPanel_) cameraPanel_->refresh();
        notes.prepend(tr("It stays open (no second handle); the config's camera settings were applied again."));
        emit notice(tr("%1 is the live camera already:").arg(description()), notes, nullptr);
        if (!nav_->isPlaying()) nav_->togglePlay();
        return;
    }
    chosen_ = std::make_pair(source, start);
    emit sourceChosen(source, start);
}

CameraOpen LiveController::openCamera(const QString& source, SimulatedStart start, const Config& config)
{
    SimulatedCameraOptions simulated;
    simulated.start = start;
    return omnitune::openCamera(source.toStdString(), config.camera.frameRate, simulated);
}

std::shared_ptr<FrameSource> LiveController::start(std::unique_ptr<Camera> camera, bool applySettings)
{
    close();
    const Config& config = doc_->config();
    liveSource_ = chosen_;  // (empty when the camera did not come from the menu)
    chosen_.reset();
    camera_ = std::make_unique<CameraFrameSource>(std::move(camera));
    replay_ = std::make_shared<ReplayBuffer>(ReplayBuffer::capacityFor(config.camera.replaySeconds, config.camera.frameRate));
    applySettings_ = applySettings;
    failed_ = false;
    pendingSeq_ = shownSeq_ = lastCameraIndex_ = -1;
    dropped_ = 0;
    shownAt_.clear();
    QStringList notes;
    if (applySettings_) this->applySettings(notes);
    emit notice(tr("Camera settings from the config (camera section) on %1:").arg(description()), notes, nullptr);
    giveCameraToPanel();
    offerFittedConfig();
    statusLabel_->show();
    grabTimer_.setInterval(int(1000.0 / std::max(config.camera.frameRate, 1.0)));
    nav_->setLive(true);  // a recorded source played: paused, then live (frames from the grab timer)
    nav_->togglePlay();
    updateActions();
    return std::make_shared<ReplaySource>(replay_, camera_->description(), camera_->frameSize());
}

void LiveController::close()
{
    if (!camera_) return;
    stopRecording();
    if (cameraPanel_) cameraPanel_->setCamera(nullptr);  // before the camera goes
    Camera& c = camera_->camera();
    nav_->setLive(false);  // paused first (onPlayingChanged sees the camera still open)
    grabTimer_.stop();
    c.stop();
    c.close();
    camera_.reset();
    liveSource_.reset();
    replay_.reset();  // the runner's ReplaySource keeps its own reference while it reads
    fitted_.reset();
    statusLabel_->clear();
    statusLabel_->hide();
    updateActions();
    emit cameraClosed();
}

Camera* LiveController::camera() const { return camera_ ? &camera_->camera() : nullptr; }

QString LiveController::description() const { return camera_ ? QString::fromStdString(camera_->description()) : QString(); }

void LiveController::applySettings(QStringList& notes)
{
    const CameraSettingsApply applied = applyCameraSettings(camera_->camera(), doc_->config().camera);
    for (const std::string& n : applied.notes) notes << QString::fromStdString(n);
    if (applied.error) notes << QString::fromStdString(applied.error->message);
}

namespace {

// The config's processed ring lies on the simulated camera's mirror: same frame size, and the
// outer circle inside the fitted one (with the fit's own margin inside the rim).
bool geometryFits(const GeometryOptions& config, const GeometryOptions& fitted)
{
    if (config.imageWidth != fitted.imageWidth || config.imageHeight != fitted.imageHeight) return false;
    const double off = std::hypot(config.centerX - fitted.centerX, config.centerY - fitted.centerY);
    return off + config.outerRadius <= fitted.outerRadius + MeasuredCalibrationOptions{}.rimMarginPx;
}

bool isBuiltInGeometry(const Config& config)
{
    const GeometryOptions d = Config{}.geometry;
    const GeometryOptions& g = config.geometry;
    return g.imageWidth == d.imageWidth && g.imageHeight == d.imageHeight && g.centerX == d.centerX &&
           g.centerY == d.centerY && g.innerRadius == d.innerRadius && g.outerRadius == d.outerRadius &&
           g.maskFile == d.maskFile && config.mask.empty();
}

}  // namespace

void LiveController::offerFittedConfig()
{
    fitted_.reset();
    const auto* simulated = dynamic_cast<const SimulatedCamera*>(&camera_->camera());
    if (!simulated) return;
    const Config& config = doc_->config();
    std::string why;
    std::optional<Config> fitted = simulated->fittedConfig(config, &why);
    if (!fitted) {
        emit notice(tr("The simulated camera's config could not be fitted:"), {QString::fromStdString(why)}, nullptr);
        return;
    }
    const bool builtIn = isBuiltInGeometry(config);
    if (!builtIn && geometryFits(config.geometry, fitted->geometry)) return;
    fitted_ = std::move(fitted);
    const GeometryOptions& g = config.geometry;
    const GeometryOptions& f = fitted_->geometry;
    const QString now = tr("%1x%2, centre (%3, %4), radii %5..%6 px")
                            .arg(g.imageWidth).arg(g.imageHeight).arg(g.centerX, 0, 'f', 1).arg(g.centerY, 0, 'f', 1)
                            .arg(g.innerRadius, 0, 'f', 0).arg(g.outerRadius, 0, 'f', 0);
    const QString fit = tr("%1x%2, centre (%3, %4), radii %5..%6 px")
                            .arg(f.imageWidth).arg(f.imageHeight).arg(f.centerX, 0, 'f', 1).arg(f.centerY, 0, 'f', 1)
                            .arg(f.innerRadius, 0, 'f', 0).arg(f.outerRadius, 0, 'f', 0);
    emit notice(builtIn ? tr("The config's geometry is the built-in default, not this camera's:")
                        : tr("The config's geometry does not fit the simulated camera's mirror:"),
                {tr("config: %1").arg(now), tr("fitted to the simulated camera: %1").arg(fit),
                 tr("Outside the mirror the panes fill with candidates; the button applies the fitted config (Undo takes it back).")},
                useFitted_);
    updateActions();
}

void LiveController::useFittedConfig()
{
    if (!fitted_) return;
    if (const auto err = doc_->replaceConfig(*fitted_, tr("Simulated camera's fitted config"))) {
        emit notice(tr("The fitted config was refused:"), {*err}, nullptr);
        return;
    }
    fitted_.reset();
    updateActions();
    emit notice(tr("The simulated camera's fitted config is applied"), {tr("Edit > Undo takes it back; File > Save keeps it.")},
                nullptr);
}

cv::Mat LiveController::usedPixels() const
{
    const Config& config = doc_->config();
    try {
        const Geometry geometry(config.geometry, config.mask);
        if (geometry.imageSize() == camera_->frameSize()) return geometry.usedMask();
    } catch (const std::exception&) {
        // a config whose geometry cannot be built: the whole frame counts
    }
    return {};  // the pixels the calibration's MSV counts: the geometry's, when it fits this camera
}

void LiveController::giveCameraToPanel()
{
    if (!cameraPanel_) return;
    cameraPanel_->setCamera(&camera_->camera(), doc_->config().cameraAuto, usedPixels());
    emit cameraOpened();
}

void LiveController::configChanged(const QString& key)
{
    // A dragged reference region, new targets or a new mask reach the panel's histogram and its
    // next calibration at once.
    if (!camera_ || !cameraPanel_) return;
    if (key.isEmpty() || key.startsWith("camera_auto.") || key.startsWith("geometry.") || key.startsWith("mask"))
        cameraPanel_->setOptions(doc_->config().cameraAuto, usedPixels());
}

bool LiveController::handleNavigation(int position)
{
    if (!camera_) return false;
    // The navigator ticks nothing while live: a position asked for is the user's step
    // (arrow, slider, Home / End), which pauses there, as a DVR does.
    if (nav_->isPlaying()) nav_->togglePlay();
    showPosition(position);
    return true;
}

void LiveController::onPlayingChanged(bool playing)
{
    if (!camera_) return;
    if (playing && failed_) {
        QTimer::singleShot(0, this, [this] {
            if (nav_->isPlaying()) nav_->togglePlay();
        });
        return;
    }
    // The slider holds exactly the buffer's frames; live, it sits on the newest.
    const int size = replay_->size();
    nav_->setFrameCount(size);
    if (playing) {
        lastCameraIndex_ = -1;  // frames the camera gave while paused are not dropped ones
        nav_->setCurrent(std::max(size - 1, 0));
        QTimer::singleShot(0, this, [this] {
            if (camera_ && nav_->isPlaying()) grabTick();  // the first frame now, not a tick later
        });
    } else {
        nav_->setCurrent(std::max(replay_->positionOf(shownSeq_), 0));
    }
    updateGrabTimer();
    updateStatus();
}

void LiveController::updateGrabTimer()
{
    // Paused, a recording still needs the camera's frames (a user who pauses to look keeps recording).
    const bool on = camera_ && !failed_ && (nav_->isPlaying() || recorder_);
    if (on && !grabTimer_.isActive()) grabTimer_.start();
    if (!on) grabTimer_.stop();
}

void LiveController::grabTick()
{
    if (!camera_ || failed_) return;
    if (cameraPanel_ && cameraPanel_->isCalibrating()) return;  // its own grabs feed the views now
    Frame frame;
    grabLive(frame);
}

std::optional<CameraError> LiveController::grabLive(Frame& frame)
{
    if (!camera_ || failed_) return CameraError{CameraErrorKind::NotStarted, tr("no live camera").toStdString()};
    if (const auto err = camera_->read(FrameSource::kNext, frame)) {
        const CameraError error{CameraErrorKind::Device, err->message};
        fail(QString::fromStdString(err->message));
        return error;
    }
    frame.index = camera_->lastCameraIndex();  // the camera's own count: gaps are frames it dropped
    if (lastCameraIndex_ >= 0) dropped_ += std::max(frame.index - lastCameraIndex_ - 1, 0);
    lastCameraIndex_ = frame.index;
    if (recorder_) recorder_->push(frame, false);
    if (cameraPanel_) cameraPanel_->showFrame(frame.image);  // histogram and MSV, throttled by the panel
    if (!nav_->isPlaying()) return std::nullopt;  // paused: the buffer stays as the user steps through it
    const int seq = replay_->push(frame);
    const int size = replay_->size();
    if (nav_->frameCount() != size) nav_->setFrameCount(size);
    nav_->setCurrent(size - 1);  // live: the slider sits on the newest frame
    offer(seq);
    updateStatus();
    return std::nullopt;
}

void LiveController::offer(int seq)
{
    if (runner_->isBusy()) {
        if (pendingSeq_ >= 0) ++dropped_;  // replaced before the pipeline got to it
        pendingSeq_ = seq;
        return;
    }
    pendingSeq_ = -1;
    shownSeq_ = seq;
    emit frameWanted(seq);
    // The window set the sequence number as the navigator's place: put the place back.
    nav_->setCurrent(nav_->isPlaying() ? replay_->size() - 1 : replay_->positionOf(seq));
}

void LiveController::showPosition(int position)
{
    pendingSeq_ = -1;  // the user's step wins over a live frame still waiting
    // The slider may still hold the extra place of live mode: the newest frame is the last.
    const int seq = replay_->seqAt(replay_->step(position, 0));
    if (seq < 0) return;
    shownSeq_ = seq;
    emit frameWanted(seq);
    nav_->setCurrent(replay_->positionOf(seq));
    updateStatus();
}

void LiveController::onRunFinished()
{
    if (!camera_) return;
    if (nav_->isPlaying()) {
        const qint64 now = clock_.elapsed();
        shownAt_.push_back(now);
        while (!shownAt_.empty() && shownAt_.front() < now - 1000) shownAt_.pop_front();
    }
    if (pendingSeq_ >= 0 && !runner_->isBusy()) offer(pendingSeq_);
}

QString LiveController::statusText() const
{
    if (!camera_) return {};
    if (failed_) return tr("camera stopped");
    if (!nav_->isPlaying()) {
        const int position = replay_->positionOf(shownSeq_);
        const QString text = tr("paused \u00b7 frame %1 of %2 in the replay buffer").arg(position + 1).arg(replay_->size());
        return recorder_ ? text + tr(" \u00b7 recording goes on") : text;
    }
    return tr("live \u00b7 %1 fps \u00b7 %2 dropped").arg(shownAt_.size()).arg(dropped_);
}

void LiveController::updateStatus()
{
    statusLabel_->setText(statusText());
    statusLabel_->setStyleSheet(failed_ ? "color: #c00000" : nav_->isPlaying() ? "color: #007000" : QString());
}

void LiveController::fail(const QString& why)
{
    failed_ = true;
    grabTimer_.stop();
    if (nav_->isPlaying()) nav_->togglePlay();
    if (cameraPanel_) cameraPanel_->setCamera(nullptr);  // the panel must not write to a dead camera
    stopRecording();
    updateStatus();
    updateActions();
    emit notice(tr("The camera stopped: %1").arg(description()),
                {why, tr("Frames so far stay in the replay buffer; Reconnect opens the camera again.")}, reconnect_);
}

void LiveController::reconnect()
{
    if (!camera_) return;
    Camera& c = camera_->camera();
    c.stop();
    c.close();
    if (const auto err = c.open()) {
        emit notice(tr("Cannot reconnect %1:").arg(description()), {QString::fromStdString(err->message)}, reconnect_);
        return;
    }
    failed_ = false;
    QStringList notes;
    if (applySettings_) applySettings(notes);
    emit notice(tr("Reconnected %1; camera settings:").arg(description()), notes, nullptr);
    giveCameraToPanel();
    updateActions();
    if (!nav_->isPlaying()) nav_->togglePlay();
}

QString LiveController::startRecording(const QString& folder)
{
    if (!camera_ || failed_) return tr("No live camera to record: open one from Camera > Live source");
    if (recorder_) return tr("Already recording to %1").arg(QString::fromStdString(recorder_->folder()));
    const Config& config = doc_->config();
    CameraRecorderOptions options;
    options.config = config;  // the session replays with the config it was recorded under
    options.minFreeBytes = std::uint64_t(std::max(config.camera.recordMinFreeMb, 0)) * 1024 * 1024;
    options.queueFrames = std::max(8, int(config.camera.frameRate));  // about a second of frames
    CameraRecorder::Start started = CameraRecorder::start(camera_->camera(), folder.toStdString(), options);
    if (!started.ok()) return QString::fromStdString(started.error);
    recorder_ = std::move(started.recorder);
    recordBar_->setRecorder(recorder_.get());
    updateGrabTimer();  // records also while the view is paused
    updateStatus();
    updateActions();
    return {};
}

void LiveController::stopRecording()
{
    if (!recorder_) return;
    recordBar_->setRecorder(nullptr);
    const CameraRecorderStatus s = recorder_->finish();
    const QString folder = QString::fromStdString(recorder_->folder());
    recorder_.reset();
    updateGrabTimer();
    updateStatus();
    updateActions();
    QStringList lines{tr("%1 frames written, %2 dropped; File > Open session or image folder replays it").arg(s.written).arg(s.dropped)};
    if (s.error) lines.prepend(QString::fromStdString(*s.error));
    emit notice(tr("Recording to %1 ended:").arg(folder), lines, nullptr);
}

void LiveController::chooseRecordingFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(window_, tr("Record into a new (or empty) folder"));
    if (folder.isEmpty()) return;
    const QString error = startRecording(folder);
    if (!error.isEmpty()) emit notice(tr("Cannot record:"), {error}, nullptr);
}

void LiveController::updateActions()
{
    record_->setEnabled(camera_ && !failed_ && !recorder_);
    stopRecord_->setEnabled(recorder_ != nullptr);
    reconnect_->setEnabled(camera_ && failed_);
    useFitted_->setEnabled(fitted_.has_value());
}

}  // namespace omnitune
