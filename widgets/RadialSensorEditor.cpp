#include "widgets/RadialSensorEditor.h"

#include "widgets/ConfigDocument.h"
#include "widgets/ImageView.h"
#include "widgets/Overlay.h"
#include "widgets/PaneEditMode.h"
#include "widgets/PaneSketch.h"
#include "widgets/PipelineRunner.h"
#include "widgets/PipelineView.h"
#include "widgets/RayStrip.h"

#include <QAction>
#include <QMenu>
#include <QPainter>

#include <cmath>

namespace omnitune {

namespace {

double wrapDegrees(double a)
{
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

double snap(double v, double step) { return std::round(v / step) * step; }

}  // namespace

RadialSensorEditor::RadialSensorEditor(ConfigDocument* doc, PipelineView* view, RayStrip* strip, QObject* parent)
    : QObject(parent), doc_(doc), view_(view), strip_(strip), drag_(doc)
{
    connectPaneInput(view_, this, &RadialSensorEditor::onPressed, &RadialSensorEditor::onDragged, &RadialSensorEditor::onReleased);
    // The rays follow every edit at once (panel, undo), before the pipeline has re-run.
    connect(doc_, &ConfigDocument::changed, this, [this] {
        if (selected_ >= doc_->config().sensors.count) selectRay(-1);
        updateSketches();
    });
    for (int i = 0; i < PipelineView::kPaneCount; ++i)
        sketches_.push_back(new PaneSketch(view_->pane(i), [this](QPainter& p, const ImageView& v) { paintRays(p, v); }));
    strip_->hide();
}

void RadialSensorEditor::fillMenu(QMenu* menu)
{
    modeAction_ = addEditModeAction(menu, this, &RadialSensorEditor::setEditing, tr("Edit &radial sensors on the panes"),
                                    QStringLiteral("editSensors"), QKeySequence(Qt::Key_R),
                                    tr("Drag the ends of a ray to set the sensors' radii, its middle to turn them; click a ray "
                                       "to see its colour classes"));
}

void RadialSensorEditor::setEditing(bool on)
{
    if (on == editing_) return;
    drag_.cancel();  // a drag cut short (Esc, R while dragging): back to where it began
    grab_ = {};
    editing_ = on;
    emit editingChanged(on);  // the other editors give the left button up first
    showEditMode(view_, this, on, modeAction_, sketches_);
    strip_->setVisible(on);
    refreshStrip();
    emit message(on ? tr("Radial sensors: drag a ray's inner or outer end to set the radii, its middle to turn all rays; "
                         "click a ray to see its classes below; R ends")
                    : tr("Radial sensor editing off"));
}

void RadialSensorEditor::selectRay(int ray)
{
    selected_ = ray;
    refreshStrip();
    updateSketches();
}

void RadialSensorEditor::setRun(std::shared_ptr<const PipelineRun> run)
{
    run_ = std::move(run);
    refreshStrip();
}

void RadialSensorEditor::refreshStrip()
{
    if (!editing_) return;  // the strip is hidden: nothing to compute
    if (run_ && selected_ >= 0)
        strip_->showRay(*run_, selected_);
    else
        strip_->clear();
}

void RadialSensorEditor::updateSketches()
{
    for (QWidget* w : sketches_) w->update();
}

double RadialSensorEditor::angleAt(QPointF p) const
{
    const GeometryOptions& g = doc_->config().geometry;
    return std::atan2(-(p.y() - g.centerY), p.x() - g.centerX) * 180.0 / M_PI;  // image y grows downwards
}

RadialSensorEditor::Grab RadialSensorEditor::grabAt(QPointF p) const
{
    const Config& c = doc_->config();
    const RadialSensorOptions& s = c.sensors;
    const double d = std::hypot(p.x() - c.geometry.centerX, p.y() - c.geometry.centerY);
    const double reach = kGrabDistance / std::max(1e-6, view_->paneScale());  // image px
    // The nearest ray by angle, and how far the press is from its line.
    const double step = 360.0 / std::max(1, s.count);
    const int ray = int(std::lround(wrapDegrees(angleAt(p) - s.angleOffsetDeg) / step)) % std::max(1, s.count);
    const double off = (angleAt(p) - radialSensorAngle(s, ray) * 180.0 / M_PI) * M_PI / 180.0;
    if (d * std::abs(std::sin(off)) > reach || std::cos(off) < 0) return {};
    if (std::abs(d - s.innerRadius) <= reach) return {Handle::Inner, ray};
    if (std::abs(d - s.outerRadius) <= reach) return {Handle::Outer, ray};
    if (d > s.innerRadius && d < s.outerRadius) return {Handle::Turn, ray};
    return {};
}

void RadialSensorEditor::onPressed(QPointF p)
{
    grab_ = grabAt(p);
    if (grab_.handle == Handle::None) {
        emit message(tr("Press on a ray (drawn while editing) to drag its end, turn it or select it"));
        return;
    }
    drag_.begin();
    startAngle_ = angleAt(p);
    selectRay(grab_.ray);
}

Config RadialSensorEditor::dragged(QPointF p) const
{
    Config c = drag_.start();
    RadialSensorOptions& s = c.sensors;
    const double d = std::hypot(p.x() - c.geometry.centerX, p.y() - c.geometry.centerY);
    switch (grab_.handle) {
    case Handle::Inner: s.innerRadius = snap(std::clamp(d, 0.0, s.outerRadius - 1.0), kRadiusStep); break;
    case Handle::Outer: s.outerRadius = snap(std::max(d, s.innerRadius + 1.0), kRadiusStep); break;
    case Handle::Turn: s.angleOffsetDeg = wrapDegrees(snap(s.angleOffsetDeg + angleAt(p) - startAngle_, kAngleStep)); break;
    case Handle::None: break;
    }
    return c;
}

void RadialSensorEditor::onDragged(QPointF p)
{
    if (grab_.handle == Handle::None) return;
    const Config next = dragged(p);
    if (next.sensors.innerRadius == doc_->config().sensors.innerRadius &&
        next.sensors.outerRadius == doc_->config().sensors.outerRadius &&
        next.sensors.angleOffsetDeg == doc_->config().sensors.angleOffsetDeg)
        return;
    drag_.show(next);
}

void RadialSensorEditor::onReleased(QPointF p)
{
    if (grab_.handle == Handle::None) return;
    onDragged(p);
    const Handle was = grab_.handle;
    grab_ = {};
    const QString what = was == Handle::Turn    ? tr("Turn radial sensors")
                         : was == Handle::Inner ? tr("Set sensors' inner radius")
                                                : tr("Set sensors' outer radius");
    std::optional<QString> refused;
    if (!drag_.finish(what, &refused) && !refused) {  // a click: the ray is selected, nothing changes
        emit message(tr("Ray %1 selected: its colour classes are under the panes").arg(selected_));
        return;
    }
    if (refused) emit message(*refused);
    const RadialSensorOptions& s = doc_->config().sensors;
    emit message(tr("Radial sensors: %1 rays from %2 to %3 px, first at %4 deg")
                     .arg(s.count).arg(s.innerRadius, 0, 'f', 1).arg(s.outerRadius, 0, 'f', 1).arg(s.angleOffsetDeg, 0, 'f', 1));
}

// Every ray with its two ends, the selected one highlighted.
void RadialSensorEditor::paintRays(QPainter& p, const ImageView& pane) const
{
    const Config& c = doc_->config();
    const RadialSensorOptions& s = c.sensors;
    const QPointF centre(c.geometry.centerX, c.geometry.centerY);
    for (int i = 0; i < s.count; ++i) {
        const double a = radialSensorAngle(s, i);
        const QPointF dir(std::cos(a), -std::sin(a));
        const QPointF from = pane.toWidget(centre + dir * s.innerRadius), to = pane.toWidget(centre + dir * s.outerRadius);
        const bool selected = i == selected_;
        p.setPen(QPen(selected ? QColor(Qt::yellow) : overlay_colour::sensors(), selected ? 3 : 1));
        p.drawLine(from, to);
        p.setPen(Qt::NoPen);
        p.setBrush(selected ? QColor(Qt::yellow) : QColor(255, 255, 255, 160));
        const double dot = selected ? 4.0 : 2.0;
        p.drawEllipse(from, dot, dot);
        p.drawEllipse(to, dot, dot);
        p.setBrush(Qt::NoBrush);
    }
}

}  // namespace omnitune
