#include "widgets/RayStrip.h"

#include "core/ColorClass.h"
#include "core/Geometry.h"
#include "widgets/PipelineRunner.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

constexpr int kBarHeight = 22;   // px of the coloured bar
constexpr double kTickPx = 50.0; // image px between radius ticks

QColor classColour(const ColourClasses& classes, ColorClass c)
{
    const int index = int(c) - 1;
    if (index < 0 || index >= int(classes.size())) return QColor(60, 60, 60);
    const auto& bgr = classes[std::size_t(index)].display;
    return QColor(bgr[2], bgr[1], bgr[0]);
}

}  // namespace

RayStrip::RayStrip(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("rayStrip"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setToolTip(tr("Colour classes along the selected radial sensor ray, from its inner radius (left) to its outer "
                  "radius (right); gaps are pixels the mask or the mirror ring leave out"));
}

QSize RayStrip::sizeHint() const { return QSize(400, kBarHeight + 2 * fontMetrics().height() + 8); }

void RayStrip::clear()
{
    ray_ = -1;
    runs_.clear();
    update();
}

void RayStrip::showRay(const PipelineRun& run, int ray)
{
    const Config& c = run.config;
    if (ray < 0 || ray >= c.sensors.count || !run.error.isEmpty() || !run.result.ok() || run.result.classes.empty()) {
        clear();
        return;
    }
    ray_ = ray;
    options_ = c.sensors;
    classes_ = c.colors.classes;
    angleDeg_ = std::fmod(radialSensorAngle(c.sensors, ray) * 180.0 / M_PI, 360.0);
    const RadialSensors sensors(c.sensors, Geometry(c.geometry, c.mask));
    sensors.runs(run.result.classes, ray, runs_);
    update();
}

void RayStrip::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 30, 30));
    const QFontMetrics fm(font());
    p.setPen(Qt::lightGray);
    if (ray_ < 0) {
        p.drawText(rect(), Qt::AlignCenter, tr("Click a ray on a pane to see its colour classes here"));
        return;
    }
    const QString title = tr("ray %1 at %2 deg, radius %3 to %4 px: %5 run(s)")
                              .arg(ray_).arg(angleDeg_, 0, 'f', 1).arg(options_.innerRadius, 0, 'f', 0)
                              .arg(options_.outerRadius, 0, 'f', 0).arg(runs_.size());
    p.drawText(QRect(6, 2, width() - 12, fm.height()), Qt::AlignLeft | Qt::AlignVCenter, title);
    const QRectF bar(6, fm.height() + 4, width() - 12, kBarHeight);
    const double span = std::max(1.0, options_.outerRadius - options_.innerRadius);
    const auto xAt = [&](double radius) { return bar.left() + (radius - options_.innerRadius) / span * bar.width(); };
    p.fillRect(bar, QColor(60, 60, 60));  // the gaps: left out by the mask or the ring
    // A run covers its pixels' radii, half a pixel step either side.
    for (const ClassRun& r : runs_) {
        const QRectF box(QPointF(xAt(r.startRadius - 0.5), bar.top()), QPointF(xAt(r.endRadius + 0.5), bar.bottom()));
        const QColor colour = classColour(classes_, r.colorClass);
        p.fillRect(box, colour);
        const QString name = QString::fromStdString(colourClassName(classes_, r.colorClass));
        if (fm.horizontalAdvance(name) + 4 < box.width()) {
            p.setPen(colour.lightness() > 128 ? Qt::black : Qt::white);
            p.drawText(box, Qt::AlignCenter, name);
        }
    }
    p.setPen(Qt::lightGray);
    for (double r = std::ceil(options_.innerRadius / kTickPx) * kTickPx; r <= options_.outerRadius; r += kTickPx) {
        const double x = xAt(r);
        p.drawLine(QPointF(x, bar.bottom()), QPointF(x, bar.bottom() + 4));
        const double left = std::clamp(x - 30, 0.0, width() - 60.0);  // the end labels stay whole
        p.drawText(QRectF(left, bar.bottom() + 4, 60, fm.height()), Qt::AlignHCenter | Qt::AlignTop, QString::number(r, 'f', 0));
    }
}

}  // namespace omnitune
