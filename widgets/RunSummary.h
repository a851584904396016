#pragma once
// What the frame on screen's run found, in words: a line under the panes (the ball in metres,
// or why nothing was found or the frame was skipped) beside the ground-truth line, and the
// stage timings with their running average for the status bar.
#include <QWidget>

class QLabel;

namespace omnitune {

struct PipelineRun;

class RunSummary : public QWidget {
    Q_OBJECT
public:
    explicit RunSummary(QWidget* parent = nullptr);

    QLabel* timingLabel() const { return timing_; }  // for the status bar
    // A new source is being opened: nothing of the previous one stays; the average restarts.
    void opening(const QString& sourceName);
    // A run that failed (`why` in full: the tooltip) or one that succeeded.
    void showUnprocessed(const PipelineRun& run, const QString& why);
    void showResult(const PipelineRun& run);
    // The truth marker's description; marking mode is shown so that it cannot be missed.
    void setTruth(const QString& text, bool marking);

private:
    QLabel* result_;
    QLabel* truth_;
    QLabel* timing_;
    double averageMs_ = 0;
    int averaged_ = 0;
};

}  // namespace omnitune
