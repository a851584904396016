#include "widgets/WholeSessionRun.h"

#include "calib/eval/Evaluation.h"
#include "widgets/BallModelPanel.h"
#include "widgets/ConfigDocument.h"
#include "widgets/FrameNavigator.h"
#include "widgets/MarkedSlider.h"
#include "widgets/SessionSweep.h"
#include "widgets/SessionSweepPanel.h"
#include "widgets/TruthDocument.h"
#include "widgets/WindowDocks.h"

#include <QSet>

namespace omnitune {

WholeSessionRun::WholeSessionRun(ConfigDocument* doc, TruthDocument* truth, FrameNavigator* nav,
                                 BallModelPanel* ballModel, WindowDocks* docks, QObject* parent)
    : QObject(parent), doc_(doc), truth_(truth), nav_(nav), ballModel_(ballModel), docks_(docks)
{
}

WholeSessionRun::~WholeSessionRun() { delete panel_; }

SessionSweepPanel* WholeSessionRun::panel() const { return panel_.data(); }

void WholeSessionRun::start(const QString& sourcePath)
{
    if (!panel_) {
        panel_ = new SessionSweepPanel(nav_);
        connect(panel_, &SessionSweepPanel::sweepFinished, this, &WholeSessionRun::onFinished);
        connect(panel_, &SessionSweepPanel::rerunRequested, this, &WholeSessionRun::rerunRequested);
        const auto outdate = [this] {
            if (!panel_->result() && !panel_->isRunning()) return;
            panel_->setOutdated(true);
            nav_->setMarksOutdated(sweepMarkKinds());
        };
        connect(doc_, &ConfigDocument::changed, panel_, outdate);
        connect(doc_, &ConfigDocument::dirtyChanged, panel_, outdate);
        connect(truth_, &TruthDocument::changed, panel_, outdate);  // its ratio and false positives
    }
    SweepRequest request;
    request.sourcePath = sourcePath;
    request.current = doc_->config();
    request.savedConfigPath = doc_->path();  // what the file holds, unsaved edits or not
    request.truth = truth_->rows();
    // A tab beside the thresholds: the panes stay in sight (a window used to cover them).
    docks_->show(panel_, tr("Whole session"), QStringLiteral("wholeSession"));
    panel_->start(std::move(request));
}

void WholeSessionRun::reset()
{
    if (panel_) panel_->reset();
}

void WholeSessionRun::onFinished(std::shared_ptr<const SweepResult> result)
{
    if (!result->ok()) {
        emit failed(QString::fromStdString(result->error));
        return;
    }
    ballModel_->setDetections(result->current);  // more samples for the ball model
    QVector<FrameMark> marks = sweepMarks(*result);
    if (result->cancelled) {  // frames the sweep never reached keep what the live pipeline marked
        QSet<int> visited;
        for (const FrameOutcome& o : result->current) visited.insert(o.frame);
        for (const FrameMark& m : nav_->slider()->marks(FrameMarkKind::Detected))
            if (!visited.contains(m.frame)) marks.push_back(m);
    }
    nav_->setMarks(marks, sweepMarkKinds());
    if (panel_->isOutdated()) nav_->setMarksOutdated(sweepMarkKinds());
    emit finished(tr("Whole session: a ball in %1 of %2 frames, %3 changed")
                      .arg(detectionCount(result->current))
                      .arg(result->visited)
                      .arg(result->comparison.changed()));
}

}  // namespace omnitune
