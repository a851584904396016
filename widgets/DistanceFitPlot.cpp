#include "widgets/DistanceFitPlot.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

constexpr int kMargin = 40;             // px left of and below the axes, for their numbers
constexpr double kResidualShare = 0.3;  // of the plot's height for the residuals
constexpr int kCurveSteps = 60;         // segments of the drawn fit

}  // namespace

DistanceFitPlot::DistanceFitPlot(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("distanceFitPlot"));
    setMinimumHeight(180);
}

void DistanceFitPlot::setData(std::vector<DistancePoint> points, std::optional<DistanceMapFit> fit)
{
    points_ = std::move(points);
    fit_ = std::move(fit);
    update();
}

void DistanceFitPlot::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 30, 30));
    p.setPen(Qt::lightGray);
    if (points_.empty()) {
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("No calibration points yet"));
        return;
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    double rMax = 1.0, dMax = 0.1;
    for (const DistancePoint& q : points_) {
        rMax = std::max(rMax, q.radiusPx);
        dMax = std::max(dMax, q.distanceM);
    }
    rMax *= 1.05;
    dMax *= 1.1;
    const QFontMetrics fm(font());
    const QRectF area(kMargin, 4 + fm.height(), width() - kMargin - 8, height() - 8 - 2 * fm.height());
    const QRectF top(area.left(), area.top(), area.width(), area.height() * (1 - kResidualShare) - 6);
    const QRectF bottom(area.left(), top.bottom() + 12, area.width(), area.bottom() - top.bottom() - 12);
    const auto x = [&](double r) { return area.left() + r / rMax * area.width(); };
    const auto y = [&](double d) { return top.bottom() - d / dMax * top.height(); };
    p.setPen(QColor(90, 90, 90));
    p.drawRect(top);
    p.drawRect(bottom);
    p.setPen(Qt::lightGray);
    p.drawText(QRectF(0, top.top(), kMargin - 3, fm.height()), Qt::AlignRight, tr("%1 m").arg(dMax, 0, 'f', 1));
    p.drawText(QRectF(0, top.bottom() - fm.height(), kMargin - 3, fm.height()), Qt::AlignRight, tr("0 m"));
    p.drawText(QRectF(area.left(), area.bottom() + 2, area.width(), fm.height()), Qt::AlignHCenter,
               tr("image radius, 0 to %1 px").arg(rMax, 0, 'f', 0));
    if (fit_) {
        QPolygonF curve;
        for (int i = 0; i <= kCurveSteps; ++i) {
            const double r = fit_->minRadiusPx + (fit_->maxRadiusPx - fit_->minRadiusPx) * i / kCurveSteps;
            curve << QPointF(x(r), y(fit_->distanceAt(r)));
        }
        p.setPen(QPen(QColor(0, 200, 255), 2));
        p.drawPolyline(curve);
        p.setPen(Qt::lightGray);
        p.drawText(QRectF(area.left(), 2, area.width(), fm.height()), Qt::AlignLeft,
                   tr("fit: RMS %1 cm, largest %2 cm").arg(fit_->rmsCm, 0, 'f', 1).arg(fit_->maxAbsCm, 0, 'f', 1));
    }
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 200, 0));
    for (const DistancePoint& q : points_) p.drawEllipse(QPointF(x(q.radiusPx), y(q.distanceM)), 3, 3);
    // Residuals: zero in the middle, scaled to the largest.
    const double mid = bottom.center().y();
    p.setPen(QColor(90, 90, 90));
    p.drawLine(QPointF(bottom.left(), mid), QPointF(bottom.right(), mid));
    if (!fit_ || fit_->residualsCm.size() != points_.size()) return;
    const double largest = std::max(1.0, fit_->maxAbsCm);
    const double perCm = (bottom.height() / 2 - 3) / largest;
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 120, 60));
    for (std::size_t i = 0; i < points_.size(); ++i)
        p.drawEllipse(QPointF(x(points_[i].radiusPx), mid - fit_->residualsCm[i] * perCm), 2.5, 2.5);
    p.setPen(Qt::lightGray);
    p.drawText(QRectF(0, bottom.top(), kMargin - 3, fm.height()), Qt::AlignRight, tr("%1 cm").arg(largest, 0, 'f', 0));
    p.drawText(QRectF(0, mid - fm.height() / 2.0, kMargin - 3, fm.height()), Qt::AlignRight, tr("0"));
}

}  // namespace omnitune
