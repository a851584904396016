#pragma once
// The camera panel: one row per feature the camera has, a slider and a spin box with the
// camera's own range and an auto toggle where the camera has an automatic mode; one switch that
// turns every automatic mode off (the image must not drift during a match); every write read
// back, a mismatch shown ("exposure is 410, asked for 400"); and the automatic calibration
// (calib/camera/CameraAutoCalibration) started, stopped and reverted from here, one iteration
// per event-loop turn, its progress in the status line and its convergence in plots
// (CalibrationPlot). showFrame() keeps a live intensity histogram with its mean sample value
// (MSV) and the reference regions' chroma and black level, at most a few times a second. The
// camera is driven on the GUI thread, one frame per event-loop turn (a real camera's grab waits
// at most one frame period, as the live view's does), so the window stays responsive. The
// frames come through a grabber: the live view's (setGrabber) puts each one into the replay
// buffer, the panes, the histogram and a recording, so the user watches the loop converge.
#include "calib/camera/Camera.h"
#include "calib/camera/CameraAutoCalibration.h"
#include "core/CameraAutoOptions.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <functional>
#include <map>
#include <memory>

class QCheckBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;

namespace omnitune {

class CalibrationPlot;
class IntensityHistogramView;

class CameraPanel : public QWidget {
    Q_OBJECT

public:
    // Live frames refresh the histogram at most this often (ms): it costs a few ms per frame.
    static constexpr int kHistogramIntervalMs = 200;

    explicit CameraPanel(QWidget* parent = nullptr);
    ~CameraPanel() override;

    // `camera` must be open and outlive the panel, or be replaced (nullptr: none) before it
    // goes. `usedMask`: the pixels the calibration's MSV counts (empty: the whole frame).
    void setCamera(Camera* camera, const CameraAutoOptions& options = {}, const cv::Mat& usedMask = {});
    // The config changed (reference regions dragged, targets edited, a new mask): the next
    // calibration and the histogram use these; a running calibration keeps its own.
    void setOptions(const CameraAutoOptions& options, const cv::Mat& usedMask);

    // Where the calibration's frames come from: `grab` (the live view's, which shows them), or
    // the camera itself when empty. It may take the camera away (setCamera(nullptr)) on a fault.
    using Grabber = std::function<std::optional<CameraError>(Frame&)>;
    void setGrabber(Grabber grab) { grabber_ = std::move(grab); }
    bool isCalibrating() const { return stepTimer_.isActive(); }

    // Reads every feature back into the controls.
    void refresh();

    // For tests and the window: the controls of one feature (null when the camera lacks it).
    QSpinBox* spinBox(CameraFeatureId id) const;
    QSlider* slider(CameraFeatureId id) const;
    QCheckBox* autoBox(CameraFeatureId id) const;
    QPushButton* allAutoOffButton() const { return allAutoOff_; }
    QPushButton* startButton() const { return start_; }
    QPushButton* stopButton() const { return stop_; }
    QPushButton* revertButton() const { return revert_; }
    QString statusText() const;
    // Beside the feature's row: what the camera holds when it differs from what was asked.
    QString mismatchText(CameraFeatureId id) const;
    // "All auto modes off" or which are on.
    QString autoStateText() const;
    IntensityHistogramView* histogramView() const { return histogram_; }
    QString msvText() const;
    CalibrationPlot* plot() const { return plot_; }
    // Live frames come at most every `ms` (tests: 0, every frame).
    void setHistogramInterval(int ms) { histogramIntervalMs_ = ms; }

public slots:
    // A live frame (BGR, 8 bits): the histogram, MSV and reference-region values, when the
    // panel is visible and the last update is older than the interval; cheap otherwise.
    void showFrame(const cv::Mat& bgr);

signals:
    // A calibration started (the live view goes live to show its frames).
    void calibrationStarted();
    // After each calibration iteration, for plots.
    void calibrationIteration(int iteration, double msv, double u, double v, double black);
    // When the calibration ends: converged or not, and the status line's text.
    void calibrationFinished(bool converged, const QString& text);

private:
    struct Row {
        QSlider* slider = nullptr;
        QSpinBox* spin = nullptr;
        QCheckBox* automatic = nullptr;
        QLabel* mismatch = nullptr;
    };
    void rebuild();
    void write(CameraFeatureId id, int value);
    void setAuto(CameraFeatureId id, bool on);
    void allAutoOff();
    void startCalibration();
    void stopCalibration(const QString& why);
    void stepCalibration();
    void revertCalibration();
    void setStatus(const QString& text, bool problem);
    void updateButtons();
    void updateAutoState();

    Camera* camera_ = nullptr;
    CameraAutoOptions options_;
    cv::Mat usedMask_;
    std::map<CameraFeatureId, Row> rows_;
    QWidget* rowsBox_ = nullptr;
    QPushButton* allAutoOff_ = nullptr;
    QPushButton* start_ = nullptr;
    QPushButton* stop_ = nullptr;
    QPushButton* revert_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* autoState_ = nullptr;
    IntensityHistogramView* histogram_ = nullptr;
    QLabel* msv_ = nullptr;
    CalibrationPlot* plot_ = nullptr;
    QElapsedTimer histogramClock_;
    int histogramIntervalMs_ = kHistogramIntervalMs;
    QTimer stepTimer_;
    std::unique_ptr<CameraAutoCalibration> calibration_;
    Grabber grabber_;
    bool refreshing_ = false;  // controls being set from the camera: no writes back
};

}  // namespace omnitune
