#include "widgets/TruthMarker.h"

#include "calib/session/TruthMarkRules.h"
#include "widgets/PaneEditMode.h"
#include "widgets/PipelineView.h"
#include "widgets/TruthDocument.h"

#include <QAction>
#include <QMenu>
#include <QMessageBox>
#include <QUndoCommand>
#include <QUndoStack>

#include <cmath>

namespace omnitune {

// One mark (or cleared mark) of one frame: the frame's row before and after. Undo and redo
// rewrite truth.csv; a command of a session no longer open does nothing but say so.
class TruthMarkCommand : public QUndoCommand {
public:
    TruthMarkCommand(TruthMarker* marker, QString path, int frame, std::optional<TruthRow> before,
                     std::optional<TruthRow> after, const QString& text)
        : marker_(marker), path_(std::move(path)), frame_(frame), before_(std::move(before)), after_(std::move(after))
    {
        setText(text);
    }
    void redo() override { result_ = step(after_, QObject::tr("Redone")); }
    void undo() override { result_ = step(before_, QObject::tr("Undone")); }
    int id() const override { return 2; }  // never merged: every mark is its own step
    const std::optional<QString>& result() const { return result_; }

private:
    std::optional<QString> step(const std::optional<TruthRow>& row, const QString& how)
    {
        const auto err = marker_->apply(path_, frame_, row);
        if (pushed_ && err) emit marker_->message(*err);
        if (pushed_ && !err) {
            emit marker_->frameRequested(frame_);  // show what the undo changed
            emit marker_->message(QObject::tr("%1 \"%2\": frame %3 is %4 again, saved to truth.csv")
                                      .arg(how, text()).arg(frame_)
                                      .arg(row ? TruthMarker::rowText(*row) : QObject::tr("not marked")));
        }
        pushed_ = true;
        return err;
    }

    TruthMarker* marker_;
    QString path_;
    int frame_;
    std::optional<TruthRow> before_;
    std::optional<TruthRow> after_;
    std::optional<QString> result_;
    bool pushed_ = false;  // the first redo is the push itself: commit() reports that one
};

TruthMarker::TruthMarker(TruthDocument* truth, PipelineView* view, QUndoStack* undo, QObject* parent)
    : QObject(parent), truth_(truth), view_(view), undo_(undo)
{
    confirm_ = [this](const QString& question) {
        return QMessageBox::question(view_, tr("Mark ground truth"), question, QMessageBox::Yes | QMessageBox::No,
                                     QMessageBox::No) == QMessageBox::Yes;
    };
    connect(view_, &PipelineView::markPressed, this, &TruthMarker::onPressed);
    connect(view_, &PipelineView::markDragged, this, &TruthMarker::onDragged);
    connect(view_, &PipelineView::markReleased, this, &TruthMarker::onReleased);
    connect(truth_, &TruthDocument::changed, this, &TruthMarker::refresh);
}

void TruthMarker::reset(int frameCount)
{
    count_ = frameCount;
    frame_ = -1;
    run_.reset();
    refusal_.clear();
    setMarking(false);  // a mode left on for the previous source would turn pans into marks
}

void TruthMarker::setFrame(int frame)
{
    frame_ = frame;
    dragging_ = false;
}

void TruthMarker::setRun(std::shared_ptr<const PipelineRun> run)
{
    run_ = std::move(run);
    refresh();
}

void TruthMarker::setMarking(bool on)
{
    if (on && !truth_->isOpen()) {
        refusal_ = truth_->closedReason();
        emit message(refusal_);
        emit markingRefused();
        on = false;
    }
    const bool was = marking_;
    marking_ = on;
    dragging_ = false;
    if (on != was) view_->setMarking(on);  // a refused "on" must not take the button from the geometry editor
    if (markingAction_) markingAction_->setChecked(on);
    for (QAction* a : markingKeys_) a->setEnabled(on);
    refresh();
    emit markingChanged(on);
}

bool TruthMarker::runIsCurrent() const { return run_ && run_->frameIndex == frame_ && run_->error.isEmpty() && run_->result.ok(); }

std::optional<QString> TruthMarker::notOnScreen() const
{
    // Marks are made on what the panes show: until frame_'s run arrives they show another
    // frame (the one before, or the last readable one), and a quick click would land there.
    if (runIsCurrent()) return std::nullopt;
    return tr("frame %1 is not on screen yet (still processing, or unreadable): mark it once it shows").arg(frame_);
}

std::optional<QString> TruthMarker::markBall(QPointF centre, double radius)
{
    if (const auto why = notOnScreen()) return why;
    const Config& c = run_->config;
    TruthRow row;
    if (const auto err = makeBallMark(c, run_->frame.size(), frame_, centre.x(), centre.y(), radius, row))
        return QString::fromStdString(*err);
    if (const auto far = radiusFarFromModel(row.radiusPx, c.ball)) {
        const QString question = tr("Frame %1: %2.\n\nKeep this mark? (In marking mode a left drag sets the ball's "
                                    "radius; the middle button pans.)").arg(frame_).arg(QString::fromStdString(*far));
        if (!confirm_(question)) return tr("mark not kept: %1").arg(QString::fromStdString(*far));
    }
    return commit(row);
}

std::optional<QString> TruthMarker::acceptDetection()
{
    if (const auto why = notOnScreen()) return why;
    return commit(detectionMark(frame_, run_->result.detection));
}

std::optional<QString> TruthMarker::markNoBall()
{
    if (const auto why = notOnScreen()) return why;
    TruthRow row;
    row.frame = frame_;
    row.ballVisible = false;
    return commit(row);
}

std::optional<QString> TruthMarker::clearMark()
{
    if (frame_ < 0) return tr("no frame on screen");
    if (!truth_->isOpen()) return truth_->closedReason();
    const TruthRow* old = truth_->row(frame_);
    if (!old) return std::nullopt;
    auto* cmd = new TruthMarkCommand(this, truth_->path(), frame_, *old, std::nullopt, tr("clear the mark of frame %1").arg(frame_));
    undo_->push(cmd);
    return cmd->result();
}

std::optional<QString> TruthMarker::commit(TruthRow row)
{
    if (frame_ < 0) return tr("no frame on screen");
    if (!truth_->isOpen()) return truth_->closedReason();
    // A robot pose recorded with the session (simulated tours have one) stays with the frame.
    QString replaced;
    std::optional<TruthRow> before;
    if (const TruthRow* old = truth_->row(frame_)) {
        before = *old;
        row.robot = old->robot;
        replaced = tr(" (replaces %1; Ctrl+Z undoes)").arg(rowText(*old));
    }
    auto* cmd = new TruthMarkCommand(this, truth_->path(), frame_, before, row, tr("mark frame %1").arg(frame_));
    undo_->push(cmd);
    if (const auto err = cmd->result()) return err;
    // Every mark is said once: a key press alone shows nothing else when the frame moves on.
    emit message(tr("Frame %1: %2, saved to truth.csv%3").arg(frame_).arg(rowText(row), replaced));
    if (advance_) emit advanceRequested();
    return std::nullopt;
}

std::optional<QString> TruthMarker::apply(const QString& path, int frame, const std::optional<TruthRow>& row)
{
    if (truth_->path() != path)
        return tr("that mark belongs to %1, which is no longer open: nothing changed").arg(path);
    return row ? truth_->set(*row) : truth_->remove(frame);
}

int TruthMarker::nextUnmarked(int from) const
{
    for (int step = 1; step <= count_; ++step) {
        const int f = (from + step) % count_;
        if (!truth_->row(f)) return f;
    }
    return -1;
}

void TruthMarker::onPressed(QPointF p)
{
    dragging_ = true;
    dragCentre_ = p;
    dragRadius_ = 0.0;
}

void TruthMarker::onDragged(QPointF p)
{
    if (!dragging_) return;
    dragRadius_ = std::hypot(p.x() - dragCentre_.x(), p.y() - dragCentre_.y());
    TruthOverlay preview;
    preview.state = TruthOverlay::Ball;
    preview.x = dragCentre_.x();
    preview.y = dragCentre_.y();
    preview.radius = dragRadius_;
    preview.marking = true;
    view_->setTruth(preview);
}

void TruthMarker::onReleased(QPointF p)
{
    if (!dragging_) return;
    dragging_ = false;
    const double radius = std::hypot(p.x() - dragCentre_.x(), p.y() - dragCentre_.y());
    if (const auto err = markBall(dragCentre_, radius < kClickRadiusPx ? 0.0 : radius)) {
        emit message(*err);
        refresh();
    }
}

void TruthMarker::refresh()
{
    TruthOverlay o;
    o.marking = marking_;
    if (const TruthRow* r = truth_->row(shownFrame())) {
        o.state = r->ballVisible ? TruthOverlay::Ball : TruthOverlay::NoBall;
        o.x = r->px;
        o.y = r->py;
        o.radius = r->radiusPx;
    }
    view_->setTruth(o);
    emit described(describe());
}

void TruthMarker::fillMenu(QMenu* menu)
{
    markingAction_ = addEditModeAction(menu, this, &TruthMarker::setMarking, tr("&Mark ground truth"), QStringLiteral("markTruth"),
                                       QKeySequence(Qt::Key_T),
                                       tr("Click the ball's centre (drag out to set the radius by hand); the middle button pans"));
    QAction* advance = menu->addAction(tr("Next frame after each mark"));
    advance->setCheckable(true);
    advance->setChecked(advance_);
    connect(advance, &QAction::toggled, this, &TruthMarker::setAdvanceAfterMark);
    menu->addSeparator();
    auto report = [this](const std::optional<QString>& err) {
        if (err) emit message(*err);
    };
    const struct {
        QString name;
        QKeySequence key;
        std::function<void()> act;
    } items[] = {
        {tr("&Accept the detector's result (ball or no ball)"), Qt::Key_A, [=] { report(acceptDetection()); }},
        {tr("&No ball in this frame"), Qt::Key_N, [=] { report(markNoBall()); }},
        {tr("&Clear this frame's mark"), Qt::Key_Delete, [=] { report(clearMark()); }},
        {tr("Next &unmarked frame"), Qt::Key_U, [this] {
             const int f = nextUnmarked(frame_);
             if (f < 0)
                 emit message(tr("Every frame is marked"));
             else
                 emit frameRequested(f);
         }},
    };
    for (const auto& item : items) {
        QAction* a = menu->addAction(item.name, this, item.act);
        a->setShortcut(item.key);
        a->setEnabled(marking_);
        markingKeys_ << a;
    }
}

QString TruthMarker::rowText(const TruthRow& r)
{
    return r.ballVisible ? tr("ball at (%1, %2) px, %3 m away").arg(r.px, 0, 'f', 0).arg(r.py, 0, 'f', 0).arg(std::hypot(r.xM, r.yM), 0, 'f', 2)
                         : tr("no ball");
}

QString TruthMarker::describe() const
{
    if (!truth_->isOpen()) return refusal_.isEmpty() ? QString() : tr("truth: %1").arg(refusal_);
    QString state = tr("truth: not marked");
    if (const TruthRow* r = truth_->row(shownFrame())) state = tr("truth: %1").arg(rowText(*r));
    const QString counts = tr("%1 | %2 of %3 frames marked").arg(state).arg(truth_->rows().size()).arg(count_);
    if (!marking_) return counts;
    return tr("MARKING TRUTH: click the ball | A detector's result | N no ball | Del clear | U next unmarked | "
              "T stop | Ctrl+Z undo\n%1").arg(counts);
}

}  // namespace omnitune
