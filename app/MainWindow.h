#pragma once
// The workbench window: wires the source, the pipeline runner, the five panes, the frame
// navigator, the tuning panel and the config document together. It owns no vision and no
// editor logic of its own: each lives in widgets/.
#include "widgets/ConfigDocument.h"
#include "calib/camera/SimulatedCamera.h"
#include "calib/source/FrameSource.h"
#include "widgets/PipelineRunner.h"
#include "widgets/TruthDocument.h"

#include <QMainWindow>

#include <memory>

class QLabel;

namespace omnitune {

class BallModelPanel;
class CameraPanel;
class CameraSetup;
class CandidateTableModel;
class ColourEditor;
class ConfigFiles;
class FrameNavigator;
class GeometryEditor;
class LiveController;
class PaneEditors;
class NoticeBar;
class PipelineView;
class SetupSequence;
class ThresholdPanel;
class RayStrip;
class RunSummary;
class SaveAsSession;
class RecentFiles;
class RecoveryFile;
class TruthMarker;
class WholeSessionRun;
class WindowDocks;
class WindowMenus;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a session folder, video, image folder or glob; loads the session's config.yml
    // when the current config has no unsaved changes (else asks). False on failure (reported).
    bool openSource(const QString& path);
    bool openConfig(const QString& path);
    // Opens a live camera (Camera > Live source; LiveController) as the source. A camera that
    // cannot be opened is reported in the notice bar and the source on screen stays.
    bool openCamera(const QString& source, omnitune::SimulatedStart start = SimulatedStart::Good);
    // A config file (.yml, .yaml) opens as the config, anything else as a source.
    bool openPath(const QString& path);

    ConfigDocument* document() { return &doc_; }
    TruthDocument* truth() { return &truth_; }
    TruthMarker* truthMarker() const { return marker_; }
    PipelineView* pipelineView() const { return view_; }
    FrameNavigator* navigator() const { return nav_; }
    NoticeBar* notices() const { return notices_; }
    ThresholdPanel* thresholdPanel() const { return panel_; }
    RecoveryFile* recovery() const { return recovery_; }
    CameraSetup* cameraSetup() const { return cameraSetup_; }
    SetupSequence* setupSequence() const { return setupSequence_; }
    BallModelPanel* ballModel() const { return ballModel_; }
    GeometryEditor* geometryEditor() const { return geometryEditor_; }
    PaneEditors* paneEditors() const { return paneEditors_; }
    ColourEditor* colourEditor() const { return colours_; }
    CandidateTableModel* candidates() const { return candidates_; }
    LiveController* live() const { return live_; }
    CameraPanel* cameraPanel() const { return cameraPanel_; }
    std::shared_ptr<const PipelineRun> lastRun() const { return lastRun_; }
    bool isProcessing() const;

public slots:
    void showFrame(int index);
    bool saveConfig();
    bool saveConfigAs();
    // File > Save as session...: the open image folder or video as a session folder, then opens it.
    bool saveAsSession();
    // Session > Apply to whole session (Ctrl+R): the current and the saved config over every
    // frame in the background (SessionSweepPanel, docked); the slider then marks what changed.
    void applyToSession();

signals:
    void runShown(int frameIndex);  // the panes show the result of this frame now

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildEditors();  // the editors on the panes and the set-up panels, before the menus
    void requestRun();
    void onRunFinished(std::shared_ptr<const PipelineRun> run);
    void clearForNewSource();
    bool maybeKeepTruth();  // retries a failed truth.csv save; asks before marks are dropped
    void updateTitle();
    void chooseSource();
    void chooseConfig();
    void openTruth(const QString& sessionFolder, cv::Size frameSize);  // frameSize: bounds the truth rows
    void chooseSourceFile();
    void offerRecoveredEdits();  // edits an earlier run left unsaved for the current config
    void showPanel(QWidget* panel);  // the distance map or ball model panel (WindowDocks)
    void offerSessionForTruth();  // marking was refused: a non-session source may become one

    ConfigDocument doc_;
    TruthDocument truth_;
    PipelineRunner runner_;
    PipelineView* view_;
    FrameNavigator* nav_;
    ThresholdPanel* panel_;
    CandidateTableModel* candidates_;
    TruthMarker* marker_;
    WindowMenus* menus_ = nullptr;
    WindowDocks* docks_ = nullptr;  // the tabs on the right: thresholds, legend, colours, camera, panels
    RecentFiles* recent_ = nullptr;  // the menus' list
    NoticeBar* notices_ = nullptr;
    ConfigFiles* configFiles_ = nullptr;  // open, save, ask; which config a source gets
    RecoveryFile* recovery_ = nullptr;  // keeps unsaved config edits through a crash
    CameraSetup* cameraSetup_ = nullptr;  // a camera the config does not fit yet
    SetupSequence* setupSequence_ = nullptr;  // the guided set-up strip
    BallModelPanel* ballModel_ = nullptr;     // samples, fit and residuals of r(d) (docked on first use)
    GeometryEditor* geometryEditor_ = nullptr;  // drag centre and radii, nudge the centre
    PaneEditors* paneEditors_ = nullptr;  // the mask and the radial sensors on the panes
    RayStrip* rayStrip_ = nullptr;        // the classes along the selected sensor ray
    ColourEditor* colours_ = nullptr;  // colour classes, sampling on the panes (Colours dock)
    CameraPanel* cameraPanel_ = nullptr;  // the live camera's features (Camera dock)
    LiveController* live_ = nullptr;      // live mode, replay buffer, recording
    RunSummary* summary_;  // the result and truth lines under the panes, the stage timings
    QLabel* pixelLabel_;
    std::shared_ptr<FrameSource> source_;  // read on the runner's thread once handed to it
    QString sourceName_;
    int frameIndex_ = 0;  // the frame asked for last
    quint64 sourceTag_ = 0;  // counts the sources opened; runs carry it
    quint64 generation_ = 1;
    std::shared_ptr<const PipelineRun> lastRun_;

    QString sourcePath_;  // the open source (not a camera): Apply to whole session opens it again
    SaveAsSession* saveAsSession_ = nullptr;
    WholeSessionRun* wholeSession_ = nullptr;  // Apply to whole session and its panel
};

}  // namespace omnitune
