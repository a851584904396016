#include "widgets/SetupSequence.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace omnitune {

namespace {

struct StepText {
    const char* title;
    const char* what;    // what to do in this step, in one or two sentences
    const char* action;  // the action button
};

// In the order of SetupSequence::Step.
const StepText kSteps[] = {
    {QT_TRANSLATE_NOOP("SetupSequence", "Centre and rim"),
     QT_TRANSLATE_NOOP("SetupSequence", "Fit the mirror centre and rim from frames of this source. Then drag the circles on "
                                        "any pane, or nudge the centre with Alt+arrow keys (a quarter pixel; Alt+Shift: a whole one), until the outer "
                                        "circle sits on the mirror's edge."),
     QT_TRANSLATE_NOOP("SetupSequence", "Fit centre and rim")},
    {QT_TRANSLATE_NOOP("SetupSequence", "Robot body"),
     QT_TRANSLATE_NOOP("SetupSequence", "Find the robot's own body in the middle (what stays put while the field moves) and "
                                        "set the inner radius just outside it. Drag the inner circle to correct it."),
     QT_TRANSLATE_NOOP("SetupSequence", "Fit robot body")},
    {QT_TRANSLATE_NOOP("SetupSequence", "Mask"),
     QT_TRANSLATE_NOOP("SetupSequence", "Propose a mask of the body, support rods and reflections from frames in which the "
                                        "robot moves; then correct it with the brush and eraser on the acquired pane "
                                        "(the mask tool bar)."),
     QT_TRANSLATE_NOOP("SetupSequence", "Auto-mask")},
    {QT_TRANSLATE_NOOP("SetupSequence", "Ball model"),
     QT_TRANSLATE_NOOP("SetupSequence", "Mark balls at several distances (Truth > Mark ground truth, T: click the centre, "
                                        "drag the radius; an image folder or video is first saved as a session, which "
                                        "marking offers) or run the whole session; then fit the expected radius r(d) in "
                                        "the Ball model panel."),
     QT_TRANSLATE_NOOP("SetupSequence", "Fit ball model")},
    {QT_TRANSLATE_NOOP("SetupSequence", "Distance map"),
     QT_TRANSLATE_NOOP("SetupSequence", "In the Distance map panel, click floor marks whose distance you measured and type "
                                        "it (or load a POINTS.csv), and give the camera height; then fit."),
     QT_TRANSLATE_NOOP("SetupSequence", "Fit distance map")},
    {QT_TRANSLATE_NOOP("SetupSequence", "Colours"),
     QT_TRANSLATE_NOOP("SetupSequence", "A first colour calibration from the frame on screen (the Colours tab's Auto "
                                        "colours); refine the classes there by sampling on the panes."),
     QT_TRANSLATE_NOOP("SetupSequence", "Auto colours")},
    {QT_TRANSLATE_NOOP("SetupSequence", "Save"),
     QT_TRANSLATE_NOOP("SetupSequence", "Save the config (and its mask beside it). The robot loads this file."),
     QT_TRANSLATE_NOOP("SetupSequence", "Save config")},
};
static_assert(sizeof(kSteps) / sizeof(kSteps[0]) == SetupSequence::StepCount, "one text per step");

}  // namespace

SetupSequence::SetupSequence(QWidget* parent)
    : QFrame(parent), title_(new QLabel(this)), body_(new QLabel(this)), apply_(new QPushButton(this)),
      back_(new QPushButton(tr("< Back"), this)), skip_(new QPushButton(tr("Skip"), this)),
      next_(new QPushButton(tr("Next >"), this)), close_(new QPushButton(tr("Close"), this))
{
    setObjectName(QStringLiteral("setupSequence"));
    setFrameShape(QFrame::StyledPanel);
    setStyleSheet(QStringLiteral("#setupSequence { background: #dff0ff; } #setupSequence QLabel { color: black; }"));
    title_->setObjectName(QStringLiteral("setupStepTitle"));
    body_->setWordWrap(true);
    body_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Room for two lines from the start: a wrapped label's height follows its width only later.
    body_->setMinimumHeight(2 * body_->fontMetrics().lineSpacing() + 2);
    apply_->setObjectName(QStringLiteral("setupApply"));
    next_->setDefault(false);
    // Title and buttons on one row, the explanation under them: a wrapped label beside
    // buttons gets squeezed to a sliver when the strip first shows.
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(6, 3, 6, 3);
    column->setSpacing(2);
    auto* row = new QHBoxLayout;
    column->addLayout(row);
    column->addWidget(body_);
    row->addWidget(title_);
    row->addStretch(1);
    for (QPushButton* b : {apply_, back_, skip_, next_, close_}) {
        b->setFocusPolicy(Qt::NoFocus);  // the arrow keys stay with the panes (nudging the centre)
        row->addWidget(b);
    }
    close_->setToolTip(tr("Leave the set-up; Camera > Set up this camera starts it again"));
    skip_->setToolTip(tr("Go on without this step; the config keeps what it has"));
    connect(apply_, &QPushButton::clicked, this, &SetupSequence::apply);
    connect(next_, &QPushButton::clicked, this, &SetupSequence::next);
    connect(skip_, &QPushButton::clicked, this, &SetupSequence::skip);
    connect(back_, &QPushButton::clicked, this, &SetupSequence::back);
    connect(close_, &QPushButton::clicked, this, [this] {
        hide();
        emit finished();
    });
    hide();
}

void SetupSequence::start()
{
    states_.fill(StepState::Open);
    outcomes_.fill(QString());
    QFrame::show();
    show(CentreRim);
}

QString SetupSequence::text() const { return title_->text() + ": " + body_->text(); }

void SetupSequence::apply()
{
    const StepActions& a = actions_[step_];
    if (!a.apply) return;
    const SetupStepOutcome out = a.apply();
    if (out.ok) states_[step_] = StepState::Applied;
    outcomes_[step_] = out.ok ? tr("Done: %1").arg(out.text) : tr("Not done: %1").arg(out.text);
    refresh();
}

void SetupSequence::next()
{
    if (step_ + 1 >= StepCount) {
        hide();
        emit finished();
        return;
    }
    show(Step(step_ + 1));
}

void SetupSequence::skip()
{
    if (states_[step_] == StepState::Open) states_[step_] = StepState::Skipped;
    next();
}

void SetupSequence::back()
{
    if (step_ > 0) show(Step(step_ - 1));
}

void SetupSequence::show(Step step)
{
    step_ = step;
    if (actions_[step].enter) actions_[step].enter();
    refresh();
    emit stepChanged(step);
}

void SetupSequence::refresh()
{
    const StepText& t = kSteps[step_];
    title_->setText(tr("<b>Set-up %1/%2: %3</b>").arg(step_ + 1).arg(int(StepCount)).arg(tr(t.title)));
    QString body = tr(t.what);
    if (!outcomes_[step_].isEmpty()) body += "<br><i>" + outcomes_[step_].toHtmlEscaped() + "</i>";
    body_->setText(body);
    apply_->setText(tr(t.action));
    apply_->setMinimumWidth(apply_->sizeHint().width());  // the whole action name, never clipped
    apply_->setEnabled(bool(actions_[step_].apply));
    back_->setEnabled(step_ > 0);
    next_->setText(step_ + 1 == StepCount ? tr("Finish") : tr("Next >"));
    // Next suggests the step was done; Skip stays for going on without it.
    next_->setEnabled(states_[step_] == StepState::Applied || !actions_[step_].apply);
    skip_->setEnabled(step_ + 1 < StepCount || states_[step_] != StepState::Applied);
}

}  // namespace omnitune
