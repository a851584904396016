#pragma once
// The window's live mode with a camera (issue 12). The camera is driven on the GUI thread
// only: the controller's own grab timer, at the camera's frame rate (the navigator's playback
// speed is for recordings and does not scale it), grabs the camera's newest frame into the
// replay buffer (calib/camera/ReplayBuffer) and asks the window to show it; the window hands
// the runner a ReplaySource, which reads the buffer by sequence number on the pipeline's thread.
// While the pipeline is busy a newer frame replaces the one waiting (dropped, never queued); the
// status label says "live · N fps · M dropped". The navigator's play / pause is live / paused
// (FrameNavigator::setLive: it ticks no frames of its own); paused, its slider, arrows and keys step through
// the frozen buffer frame by frame, as SSL-Vision's DVR does; a step asked for while live
// pauses there. Recording hands every grabbed frame to a CameraRecorder (its own writer thread;
// RecordBar shows it), also while the view is paused. The camera panel's automatic calibration
// grabs through grabLive(), so its frames reach the panes, the histogram and a recording. A
// camera fault stops live mode and recording (its frames kept) and offers Reconnect.
#include "calib/camera/CameraCatalog.h"
#include "calib/camera/CameraRecorder.h"
#include "calib/camera/ReplayBuffer.h"
#include "calib/source/FrameSource.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <deque>
#include <memory>
#include <optional>
#include <utility>

class QAction;
class QLabel;
class QMenu;
class QWidget;

namespace omnitune {

class CameraFrameSource;
class CameraPanel;
class ConfigDocument;
class FrameNavigator;
class PipelineRunner;
class RecordBar;

class LiveController : public QObject {
    Q_OBJECT
public:
    LiveController(ConfigDocument* doc, FrameNavigator* nav, PipelineRunner* runner, CameraPanel* cameraPanel,
                   QWidget* window);
    ~LiveController() override;

    // Camera > Source (CameraSourceMenu), Record..., Stop recording, Reconnect camera.
    void fillMenu(QMenu* camera);
    QLabel* statusLabel() const { return statusLabel_; }  // for the status bar
    RecordBar* recordBar() const { return recordBar_; }   // for under the panes
    QAction* reconnectAction() const { return reconnect_; }
    // "Use the simulated camera's fitted config": offered (a notice with this button) when the
    // simulated camera opens under a config that does not fit its optics; one undo step.
    QAction* useFittedConfigAction() const { return useFitted_; }

    // Opens camera `source` (CameraCatalog) with the config's frame rate; nothing live changes.
    static CameraOpen openCamera(const QString& source, SimulatedStart start, const Config& config);
    // Makes `camera` (open) the live source: writes the config's camera section to it when
    // `applySettings` (a simulated camera started badly set keeps its bad start), sizes the
    // replay buffer (camera.replay_seconds), gives the camera to the panel and plays. The
    // FrameSource the window hands the runner; frames come through frameWanted().
    std::shared_ptr<FrameSource> start(std::unique_ptr<Camera> camera, bool applySettings);
    // Stops recording and live mode and closes the camera (the panel lets go of it first).
    void close();
    bool isOpen() const { return camera_ != nullptr; }
    Camera* camera() const;
    const ReplayBuffer* replay() const { return replay_.get(); }
    int dropped() const { return dropped_; }
    // The live grab timer's period (ms): 1000 / camera.frame_rate, whatever the playback speed.
    int grabIntervalMs() const { return grabTimer_.interval(); }
    QString statusText() const;

    // The navigator asked for `position`: while live, a tick (grab the newest frame); paused,
    // a step in the replay buffer. False when no camera is open (the window shows the frame).
    bool handleNavigation(int position);

    // Records the live frames into a new session in `folder`; an error message, or empty.
    QString startRecording(const QString& folder);
    void stopRecording();
    bool isRecording() const { return recorder_ != nullptr; }
    const CameraRecorder* recorder() const { return recorder_.get(); }

    // After a fault: opens the camera again and goes live.
    void reconnect();

    // Grabs the camera's newest frame into the views (replay buffer and panes while live, the
    // recording, the panel's histogram): the grab timer's and the panel's calibration's grab. A
    // fault stops live mode (fail()) and is returned.
    std::optional<CameraError> grabLive(Frame& frame);

signals:
    void sourceChosen(const QString& source, omnitune::SimulatedStart start);  // Camera > Source
    void frameWanted(int seq);        // show replay frame `seq` (MainWindow::showFrame)
    void cameraOpened();              // the panel has the camera (dock it into view)
    void cameraClosed();              // the panel has let go of it (nothing to show there)
    // For the notice bar: a fault, settings the camera holds differently, a recording's end.
    // `button` (may be null) goes with it (Reconnect).
    void notice(const QString& title, const QStringList& lines, QAction* button);

private:
    void onSourceChosen(const QString& source, SimulatedStart start);
    void grabTick();
    void updateGrabTimer();
    void offer(int seq);
    void showPosition(int position);
    void onPlayingChanged(bool playing);
    void onRunFinished();
    void fail(const QString& why);
    void applySettings(QStringList& notes);
    void offerFittedConfig();
    void useFittedConfig();
    void giveCameraToPanel();
    void configChanged(const QString& key);
    cv::Mat usedPixels() const;  // the geometry's used ring when it fits the camera, else empty (whole frame)
    void updateStatus();
    void updateActions();
    void chooseRecordingFolder();
    QString description() const;

    ConfigDocument* doc_;
    FrameNavigator* nav_;
    PipelineRunner* runner_;
    QPointer<CameraPanel> cameraPanel_;
    QWidget* window_;
    QLabel* statusLabel_;
    RecordBar* recordBar_;
    QAction* record_ = nullptr;
    QAction* stopRecord_ = nullptr;
    QAction* reconnect_ = nullptr;
    QAction* useFitted_ = nullptr;
    std::optional<Config> fitted_;  // the simulated camera's fitted config while offered

    std::unique_ptr<CameraFrameSource> camera_;  // GUI thread only
    QTimer grabTimer_;                           // live, or recording while paused
    // Camera > Live source: the choice start() makes live, and the one that is live.
    std::optional<std::pair<QString, SimulatedStart>> chosen_, liveSource_;
    std::shared_ptr<ReplayBuffer> replay_;
    std::unique_ptr<CameraRecorder> recorder_;
    bool applySettings_ = false;
    bool failed_ = false;
    int pendingSeq_ = -1;      // grabbed while the pipeline was busy; shown when it is free
    int shownSeq_ = -1;        // asked for last
    int lastCameraIndex_ = -1; // the camera's own index of the last frame (gaps: it dropped)
    int dropped_ = 0;
    std::deque<qint64> shownAt_;  // ms of the runs shown in the last second, for the fps
    QElapsedTimer clock_;
};

}  // namespace omnitune
