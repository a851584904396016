#pragma once
// The workbench window: wires the source, the pipeline runner, the five panes, the frame
// navigator, the tuning panel and the config document together. It owns no vision and no
// editor logic of its own: each lives in widgets/.
#include "ConfigDocument.h"
#include "FrameSource.h"
#include "PipelineRunner.h"

#include <QMainWindow>

#include <memory>

class QLabel;

namespace omnitune {

class CandidateTableModel;
class FrameNavigator;
class PipelineView;
class ThresholdPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a session folder, video, image folder or glob; loads the session's config.yml
    // when the current config has no unsaved changes (else asks). False on failure (reported).
    bool openSource(const QString& path);
    bool openConfig(const QString& path);

    ConfigDocument* document() { return &doc_; }
    PipelineView* pipelineView() const { return view_; }
    FrameNavigator* navigator() const { return nav_; }
    ThresholdPanel* thresholdPanel() const { return panel_; }
    CandidateTableModel* candidates() const { return candidates_; }
    std::shared_ptr<const PipelineRun> lastRun() const { return lastRun_; }
    bool isProcessing() const;

public slots:
    void showFrame(int index);
    bool saveConfig();
    bool saveConfigAs();

signals:
    void runShown(int frameIndex);  // the panes show the result of this frame now

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void buildMenus();
    void requestRun();
    void onRunFinished(std::shared_ptr<const PipelineRun> run);
    bool maybeSave();
    void updateTitle();
    void chooseSource();
    void chooseConfig();

    ConfigDocument doc_;
    PipelineRunner runner_;
    PipelineView* view_;
    FrameNavigator* nav_;
    ThresholdPanel* panel_;
    CandidateTableModel* candidates_;
    QLabel* resultLabel_;
    QLabel* timingLabel_;
    QLabel* pixelLabel_;
    std::unique_ptr<FrameSource> source_;
    QString sourceName_;
    Frame frame_;
    bool haveFrame_ = false;
    quint64 generation_ = 1;
    std::shared_ptr<const PipelineRun> lastRun_;
    double averageMs_ = 0;
    int averaged_ = 0;
};

}  // namespace omnitune
