#pragma once
// The panel of "Session > Apply to whole session" (the window docks it beside the panes): a
// progress bar and Cancel while the sweep runs, then the numbers of the current config beside
// the saved one (frames, balls found, detection ratio and false positives when there is truth,
// time per frame) and the frames that changed, each a click away on the frame navigator.
#include "widgets/SessionSweep.h"

#include <QWidget>

#include <memory>

class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace omnitune {

class FrameNavigator;

class SessionSweepPanel : public QWidget {
    Q_OBJECT
public:
    explicit SessionSweepPanel(FrameNavigator* navigator, QWidget* parent = nullptr);
    ~SessionSweepPanel() override;

    // Starts a sweep (cancelling one still running) and shows its progress.
    void start(SweepRequest request);
    void cancel();
    // Forgets the results (another source was opened); cancels a running sweep.
    void reset();
    bool isRunning() const { return sweep_ != nullptr; }
    const SweepResult* result() const { return result_.get(); }

    // The config changed after the sweep started: the numbers and marks describe an older one.
    void setOutdated(bool outdated);
    bool isOutdated() const { return outdated_; }

    // The results as plain text (what the table and labels say), for copying and tests.
    QString summaryText() const;

    // Jumps the navigator to the next / previous changed frame after / before its current
    // one (wrapping); false when nothing changed.
    bool nextChange();
    bool previousChange();

signals:
    void sweepProgress(int done, int total);
    void sweepFinished(std::shared_ptr<const omnitune::SweepResult> result);
    void rerunRequested();

private:
    void onProgress(int done, int total);
    void onFinished(std::shared_ptr<const SweepResult> result);
    void showRunning(bool running);
    void showResult();
    void fillTable(const SweepResult& r);
    void fillChanges(const SweepResult& r);
    bool jumpToChange(int step);

    FrameNavigator* navigator_;
    std::unique_ptr<SessionSweep> sweep_;
    std::shared_ptr<const SweepResult> result_;
    quint64 runId_ = 0;  // the sweep whose signals count
    bool outdated_ = false;

    QLabel* status_;
    QProgressBar* progressBar_;
    QPushButton* cancelButton_;
    QLabel* note_;
    QTableWidget* table_;
    QLabel* changes_;
    QListWidget* changeList_;
    QPushButton* previousButton_;
    QPushButton* nextButton_;
    QLabel* outdatedNote_;
    QPushButton* rerunButton_;
};

}  // namespace omnitune
