#pragma once
// The guided set-up of a new camera (issue 11): a strip above the panes that walks through
// centre and rim, robot body, mask, ball model, distance map, colours and save, one step at a
// time. Each step says what to do, offers its action (a fit, an auto-mask, opening the panel
// that does the work) and Back / Skip / Next; nothing blocks the window, so the user drags,
// paints and clicks on the panes between the steps. Every applied step is one undo command,
// made by the class that owns that work (CameraSetup, the panels); this class holds only
// where in the sequence the user is and what each step did.
#include "widgets/CameraSetup.h"

#include <QFrame>

#include <array>
#include <functional>

class QLabel;
class QPushButton;

namespace omnitune {

class SetupSequence : public QFrame {
    Q_OBJECT
public:
    enum Step { CentreRim, Body, Mask, BallModel, DistanceMap, Colours, Save, StepCount };
    enum class StepState { Open, Applied, Skipped };

    // What a step does beyond saying what it is: `enter` when the step is shown (open a
    // panel, start an editor; may be empty), `apply` for its action button.
    struct StepActions {
        std::function<void()> enter;
        std::function<SetupStepOutcome()> apply;
    };

    explicit SetupSequence(QWidget* parent = nullptr);
    void setActions(Step step, StepActions actions) { actions_[step] = std::move(actions); }

    // Shows the strip at the first step, every step open again.
    void start();
    Step step() const { return step_; }
    StepState state(Step step) const { return states_[step]; }
    QString text() const;  // the step's explanation and its last outcome

    // The buttons, for the keyboard-less and for tests.
    QPushButton* applyButton() const { return apply_; }
    QPushButton* nextButton() const { return next_; }
    QPushButton* skipButton() const { return skip_; }
    QPushButton* backButton() const { return back_; }
    QPushButton* closeButton() const { return close_; }

public slots:
    void apply();
    void next();
    void skip();
    void back();

signals:
    void stepChanged(int step);
    void finished();  // passed the last step, or closed

private:
    void show(Step step);
    void refresh();

    std::array<StepActions, StepCount> actions_;
    std::array<StepState, StepCount> states_{};
    std::array<QString, StepCount> outcomes_;
    Step step_ = CentreRim;
    QLabel* title_;
    QLabel* body_;
    QPushButton* apply_;
    QPushButton* back_;
    QPushButton* skip_;
    QPushButton* next_;
    QPushButton* close_;
};

}  // namespace omnitune
