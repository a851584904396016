#include "widgets/TruthMarker.h"

#include "core/BallModel.h"
#include "core/BallPosition.h"
#include "widgets/PipelineView.h"
#include "widgets/TruthDocument.h"

#include <QAction>
#include <QMenu>

#include <cmath>
#include <functional>

namespace omnitune {

TruthMarker::TruthMarker(TruthDocument* truth, PipelineView* view, QObject* parent)
    : QObject(parent), truth_(truth), view_(view)
{
    connect(view_, &PipelineView::markPressed, this, &TruthMarker::onPressed);
    connect(view_, &PipelineView::markDragged, this, &TruthMarker::onDragged);
    connect(view_, &PipelineView::markReleased, this, &TruthMarker::onReleased);
    connect(truth_, &TruthDocument::changed, this, &TruthMarker::refresh);
}

void TruthMarker::setFrameCount(int count)
{
    count_ = count;
    refresh();
}

void TruthMarker::setFrame(int frame)
{
    frame_ = frame;
    dragging_ = false;
    refresh();
}

void TruthMarker::setRun(std::shared_ptr<const PipelineRun> run) { run_ = std::move(run); }

void TruthMarker::setMarking(bool on)
{
    marking_ = on;
    dragging_ = false;
    view_->setMarking(on);
    refresh();
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
    const cv::Mat& image = run_->frame;
    if (centre.x() < 0 || centre.y() < 0 || centre.x() >= image.cols || centre.y() >= image.rows)
        return tr("the ball's centre must lie inside the image");
    const double distancePx = std::hypot(centre.x() - c.geometry.centerX, centre.y() - c.geometry.centerY);
    if (radius <= 0) radius = BallModel(c.ball).radiusAt(distancePx);
    TruthRow row;
    row.frame = frame_;
    row.ballVisible = true;
    row.px = centre.x();
    row.py = centre.y();
    row.radiusPx = radius;
    try {
        const BallPosition at = ballPositionAt(row.px, row.py, c.geometry.centerX, c.geometry.centerY, DistanceMap(c.distanceMap));
        row.xM = at.xM;
        row.yM = at.yM;
    } catch (const std::exception& e) {
        return tr("the config's distance map is not usable: %1").arg(QString::fromStdString(e.what()));
    }
    return commit(row);
}

std::optional<QString> TruthMarker::acceptDetection()
{
    if (const auto why = notOnScreen()) return why;
    const BallDetection& d = run_->result.detection;
    if (!d.found) return markNoBall();
    TruthRow row;
    row.frame = frame_;
    row.ballVisible = true;
    row.px = d.px;
    row.py = d.py;
    row.radiusPx = d.radiusPx;
    row.xM = d.xM;
    row.yM = d.yM;
    return commit(row);
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
    return truth_->remove(frame_);
}

std::optional<QString> TruthMarker::commit(TruthRow row)
{
    if (frame_ < 0) return tr("no frame on screen");
    // A robot pose recorded with the session (simulated tours have one) stays with the frame.
    QString replaced;
    if (const TruthRow* old = truth_->row(frame_)) {
        row.robot = old->robot;
        replaced = tr(" (replaces %1; mark again or Delete to change it)").arg(rowText(*old));
    }
    if (const auto err = truth_->set(row)) return err;
    // Every mark is said once: a key press alone shows nothing else when the frame moves on.
    emit message(tr("Frame %1: %2, saved to truth.csv%3").arg(frame_).arg(rowText(row), replaced));
    if (advance_) emit advanceRequested();
    return std::nullopt;
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
    if (const TruthRow* r = truth_->row(frame_)) {
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
    QAction* marking = menu->addAction(tr("&Mark ground truth"));
    marking->setObjectName("markTruth");
    marking->setCheckable(true);
    marking->setShortcut(Qt::Key_T);
    marking->setStatusTip(tr("Click the ball's centre (drag out to set the radius by hand); the middle button pans"));
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
    QList<QAction*> keyed;
    for (const auto& item : items) {
        QAction* a = menu->addAction(item.name, this, item.act);
        a->setShortcut(item.key);
        a->setEnabled(false);
        keyed << a;
    }
    connect(marking, &QAction::toggled, this, [this, keyed](bool on) {
        setMarking(on);
        for (QAction* a : keyed) a->setEnabled(on);
        if (on && !truth_->isOpen()) emit message(truth_->closedReason());
    });
}

QString TruthMarker::rowText(const TruthRow& r)
{
    return r.ballVisible ? tr("ball at (%1, %2) px, %3 m away").arg(r.px, 0, 'f', 0).arg(r.py, 0, 'f', 0).arg(std::hypot(r.xM, r.yM), 0, 'f', 2)
                         : tr("no ball");
}

QString TruthMarker::describe() const
{
    if (!truth_->isOpen()) return marking_ ? tr("truth: %1").arg(truth_->closedReason()) : QString();
    QString state = tr("truth: not marked");
    if (const TruthRow* r = truth_->row(frame_)) state = tr("truth: %1").arg(rowText(*r));
    const QString counts = tr("%1 | %2 of %3 frames marked").arg(state).arg(truth_->rows().size()).arg(count_);
    if (!marking_) return counts;
    return tr("MARKING TRUTH: click the ball | A detector's result | N no ball | Del clear | U next unmarked | "
              "T stop\n%1").arg(counts);
}

}  // namespace omnitune
