#include "widgets/CurveFitPlot.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

constexpr int kMargin = 40;             // px left of and below the axes, for their numbers
constexpr double kResidualShare = 0.3;  // of the plot's height for the residuals
constexpr int kCurveSteps = 60;         // segments of the drawn fit

}  // namespace

CurveFitPlot::CurveFitPlot(QWidget* parent) : QWidget(parent) { setMinimumHeight(180); }

void CurveFitPlot::setPlot(CurveFitPlotData data)
{
    data_ = std::move(data);
    update();
}

void CurveFitPlot::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 30, 30));
    p.setPen(Qt::lightGray);
    const auto& samples = data_.samples;
    if (samples.empty()) {
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, data_.empty);
        return;
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    double xMax = 1.0, yMax = 0.1;
    for (const QPointF& s : samples) {
        xMax = std::max(xMax, s.x());
        yMax = std::max(yMax, s.y());
    }
    xMax *= 1.05;
    yMax *= 1.1;
    const QFontMetrics fm(font());
    // Wide enough for the y axis' largest number and its unit ("21 px" was cut to "1 px").
    const QString yTop = QStringLiteral("%1 %2").arg(yMax, 0, 'f', yMax < 10 ? 1 : 0).arg(data_.yUnit);
    const int margin = std::max(kMargin, fm.horizontalAdvance(yTop) + 6);
    const QRectF area(margin, 4 + fm.height(), width() - margin - 8, height() - 8 - 2 * fm.height());
    const QRectF top(area.left(), area.top(), area.width(), area.height() * (1 - kResidualShare) - 6);
    const QRectF bottom(area.left(), top.bottom() + 12, area.width(), area.bottom() - top.bottom() - 12);
    const auto x = [&](double v) { return area.left() + v / xMax * area.width(); };
    const auto y = [&](double v) { return top.bottom() - v / yMax * top.height(); };
    p.setPen(QColor(90, 90, 90));
    p.drawRect(top);
    p.drawRect(bottom);
    p.setPen(Qt::lightGray);
    const QRectF yLabel(0, top.top(), margin - 3, fm.height());
    p.drawText(yLabel, Qt::AlignRight, yTop);
    p.drawText(yLabel.translated(0, top.height() - fm.height()), Qt::AlignRight, QStringLiteral("0 %1").arg(data_.yUnit));
    p.drawText(QRectF(area.left(), area.bottom() + 2, area.width(), fm.height()), Qt::AlignHCenter,
               tr("%1, 0 to %2 %3").arg(data_.xName).arg(xMax, 0, 'f', 0).arg(data_.xUnit));
    if (data_.curve) {
        QPolygonF curve;
        for (int i = 0; i <= kCurveSteps; ++i) {
            const double v = data_.curveFrom + (data_.curveTo - data_.curveFrom) * i / kCurveSteps;
            curve << QPointF(x(v), y(data_.curve(v)));
        }
        p.setPen(QPen(QColor(0, 200, 255), 2));
        p.drawPolyline(curve);
    }
    p.setPen(Qt::lightGray);
    p.drawText(QRectF(area.left(), 2, area.width(), fm.height()), Qt::AlignLeft, data_.summary);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 200, 0));
    for (const QPointF& s : samples) p.drawEllipse(QPointF(x(s.x()), y(s.y())), 3, 3);
    // Residuals: zero in the middle, scaled to the largest.
    const double mid = bottom.center().y();
    p.setPen(QColor(90, 90, 90));
    p.drawLine(QPointF(bottom.left(), mid), QPointF(bottom.right(), mid));
    if (data_.residuals.size() != samples.size()) return;
    double largest = 0.0;
    for (double r : data_.residuals) largest = std::max(largest, std::abs(r));
    largest = std::max(1.0, std::ceil(largest));
    const double perUnit = (bottom.height() / 2 - 3) / largest;
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 120, 60));
    for (std::size_t i = 0; i < samples.size(); ++i)
        p.drawEllipse(QPointF(x(samples[i].x()), mid - data_.residuals[i] * perUnit), 2.5, 2.5);
    p.setPen(Qt::lightGray);
    p.drawText(QRectF(0, bottom.top(), margin - 3, fm.height()), Qt::AlignRight,
               QStringLiteral("%1 %2").arg(largest, 0, 'f', 0).arg(data_.residualUnit));
    p.drawText(QRectF(0, mid - fm.height() / 2.0, margin - 3, fm.height()), Qt::AlignRight, QStringLiteral("0"));
}

}  // namespace omnitune
