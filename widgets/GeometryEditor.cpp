#include "widgets/GeometryEditor.h"

#include "widgets/ConfigDocument.h"
#include "widgets/PaneEditMode.h"
#include "widgets/PipelineView.h"

#include <QAction>
#include <QMenu>

#include <cmath>

namespace omnitune {

GeometryEditor::GeometryEditor(ConfigDocument* doc, PipelineView* view, QObject* parent)
    : QObject(parent), doc_(doc), view_(view), drag_(doc)
{
    connect(view_, &PipelineView::geometryPressed, this, &GeometryEditor::onPressed);
    connect(view_, &PipelineView::geometryDragged, this, &GeometryEditor::onDragged);
    connect(view_, &PipelineView::geometryReleased, this, &GeometryEditor::onReleased);
}

void GeometryEditor::setEditing(bool on)
{
    if (on == editing_) return;
    editing_ = on;
    // Switched off mid-drag (another editor took the left button): the drag is cancelled, so the
    // live-applied position must not stay behind without an undo step.
    drag_.cancel();
    grabbed_ = Handle::None;
    emit editingChanged(on);  // truth marking gives the left button up first
    view_->setEditingGeometry(on);
    if (modeAction_) modeAction_->setChecked(on);
    emit message(on ? tr("Editing the geometry: drag the centre cross or a yellow circle; Alt+arrows nudge the centre "
                         "(Shift: 1 px); G ends")
                    : tr("Geometry editing off"));
}

void GeometryEditor::nudge(double dx, double dy)
{
    const GeometryOptions& g = doc_->config().geometry;
    Config next = doc_->config();
    next.geometry.centerX = std::round((g.centerX + dx) / kFineStepPx) * kFineStepPx;
    next.geometry.centerY = std::round((g.centerY + dy) / kFineStepPx) * kFineStepPx;
    if (const auto why = doc_->replaceConfig(next, tr("Nudge centre"))) {
        emit message(*why);
        return;
    }
    emit message(tr("Centre (%1, %2) px").arg(next.geometry.centerX, 0, 'f', 2).arg(next.geometry.centerY, 0, 'f', 2));
}

void GeometryEditor::fillMenu(QMenu* menu)
{
    modeAction_ = addEditModeAction(menu, this, &GeometryEditor::setEditing, tr("&Edit centre and radii on the panes"),
                                    QStringLiteral("editGeometry"), QKeySequence(Qt::Key_G),
                                    tr("Drag the centre and the radii on the panes; Alt+arrows nudge the centre"));
    const struct {
        QKeySequence key;
        double dx, dy;
    } nudges[] = {
        {QKeySequence(Qt::ALT + Qt::Key_Left), -kFineStepPx, 0},   {QKeySequence(Qt::ALT + Qt::Key_Right), kFineStepPx, 0},
        {QKeySequence(Qt::ALT + Qt::Key_Up), 0, -kFineStepPx},     {QKeySequence(Qt::ALT + Qt::Key_Down), 0, kFineStepPx},
        {QKeySequence(Qt::ALT + Qt::SHIFT + Qt::Key_Left), -kCoarseStepPx, 0},
        {QKeySequence(Qt::ALT + Qt::SHIFT + Qt::Key_Right), kCoarseStepPx, 0},
        {QKeySequence(Qt::ALT + Qt::SHIFT + Qt::Key_Up), 0, -kCoarseStepPx},
        {QKeySequence(Qt::ALT + Qt::SHIFT + Qt::Key_Down), 0, kCoarseStepPx}};
    QMenu* nudgeMenu = menu->addMenu(tr("&Nudge centre"));
    for (const auto& n : nudges) {
        QAction* a = nudgeMenu->addAction(n.key.toString(QKeySequence::NativeText));
        a->setShortcut(n.key);
        connect(a, &QAction::triggered, this, [this, dx = n.dx, dy = n.dy] { nudge(dx, dy); });
    }
}

void GeometryEditor::onPressed(QPointF p)
{
    const GeometryOptions& g = doc_->config().geometry;
    const double reach = kGrabDistance / std::max(1e-6, view_->paneScale());  // image px
    const QPointF centre(g.centerX, g.centerY);
    const double d = std::hypot(p.x() - centre.x(), p.y() - centre.y());
    grabbed_ = Handle::None;
    if (d <= reach)
        grabbed_ = Handle::Centre;
    else if (std::abs(d - g.outerRadius) <= reach && std::abs(d - g.outerRadius) <= std::abs(d - g.innerRadius))
        grabbed_ = Handle::Outer;
    else if (std::abs(d - g.innerRadius) <= reach)
        grabbed_ = Handle::Inner;
    if (grabbed_ == Handle::None) {
        emit message(tr("Press on the centre cross or on a yellow circle to drag it"));
        return;
    }
    drag_.begin();
    grabOffset_ = centre - p;
}

Config GeometryEditor::dragged(Handle handle, QPointF p) const
{
    Config c = drag_.start();
    GeometryOptions& g = c.geometry;
    const double d = std::hypot(p.x() - g.centerX, p.y() - g.centerY);
    switch (handle) {
    case Handle::Centre:
        g.centerX = std::round((p.x() + grabOffset_.x()) / kFineStepPx) * kFineStepPx;
        g.centerY = std::round((p.y() + grabOffset_.y()) / kFineStepPx) * kFineStepPx;
        break;
    case Handle::Outer: g.outerRadius = std::round(std::max(d, g.innerRadius + 1.0) * 4.0) / 4.0; break;
    case Handle::Inner: g.innerRadius = std::round(std::min(d, g.outerRadius - 1.0) * 4.0) / 4.0; break;
    case Handle::None: break;
    }
    return c;
}

void GeometryEditor::onDragged(QPointF p)
{
    if (grabbed_ == Handle::None) return;
    drag_.show(dragged(grabbed_, p));
}

void GeometryEditor::onReleased(QPointF p)
{
    if (grabbed_ == Handle::None) return;
    const Handle was = grabbed_;
    grabbed_ = Handle::None;
    drag_.show(dragged(was, p));  // an invalid release point keeps the drag's last valid position
    const QString what = was == Handle::Centre ? tr("Move centre") : was == Handle::Outer ? tr("Set outer radius") : tr("Set inner radius");
    std::optional<QString> refused;
    drag_.finish(what, &refused);
    if (refused) emit message(*refused);
    const GeometryOptions& g = doc_->config().geometry;
    emit message(tr("Centre (%1, %2) px, inner radius %3 px, outer radius %4 px")
                     .arg(g.centerX, 0, 'f', 2).arg(g.centerY, 0, 'f', 2).arg(g.innerRadius, 0, 'f', 2)
                     .arg(g.outerRadius, 0, 'f', 2));
}

}  // namespace omnitune
