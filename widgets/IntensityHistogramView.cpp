#include "widgets/IntensityHistogramView.h"

#include <QPainter>

#include <algorithm>
#include <numeric>

namespace omnitune {

IntensityHistogramView::IntensityHistogramView(QWidget* parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setToolTip(tr("Share of the used pixels in each intensity region, dark to bright. The line marks the mean "
                  "sample value (MSV), the green band its target and tolerance (camera_auto.msv_*)"));
}

void IntensityHistogramView::setHistogram(std::vector<double> histogram, double msv, double target, double tolerance)
{
    histogram_ = std::move(histogram);
    msv_ = msv;
    target_ = target;
    tolerance_ = tolerance;
    update();
}

void IntensityHistogramView::clear()
{
    histogram_.clear();
    update();
}

void IntensityHistogramView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF area = QRectF(rect()).adjusted(4, 4, -4, -4);
    p.fillRect(area, palette().base());
    const double total = std::accumulate(histogram_.begin(), histogram_.end(), 0.0);
    if (histogram_.empty() || total <= 0) {
        p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
        p.drawText(area, Qt::AlignCenter, tr("no frame"));
        return;
    }
    const int n = int(histogram_.size());
    const double w = area.width() / n;
    // MSV j+1 is the middle of bar j: x(m) = left + (m - 0.5) * w.
    const auto xOf = [&](double m) { return area.left() + (m - 0.5) * w; };
    p.fillRect(QRectF(QPointF(xOf(target_ - tolerance_), area.top()), QPointF(xOf(target_ + tolerance_), area.bottom())),
               QColor(60, 170, 80, 70));
    const double tallest = *std::max_element(histogram_.begin(), histogram_.end()) / total;
    for (int j = 0; j < n; ++j) {
        const double share = histogram_[std::size_t(j)] / total;
        const double h = (area.height() - 14) * share / std::max(tallest, 1e-9);
        const int grey = n > 1 ? 40 + 190 * j / (n - 1) : 128;  // the bar's colour is its intensity
        const QRectF bar(area.left() + j * w + 2, area.bottom() - h, w - 4, h);
        p.fillRect(bar, QColor(grey, grey, grey));
        p.setPen(palette().color(QPalette::Text));
        p.drawRect(bar);
        p.drawText(QRectF(bar.left(), area.top(), bar.width(), 14), Qt::AlignCenter,
                   QStringLiteral("%1%").arg(share * 100, 0, 'f', 0));
    }
    p.setPen(QPen(QColor(200, 30, 30), 2));
    p.drawLine(QPointF(xOf(msv_), area.top() + 14), QPointF(xOf(msv_), area.bottom()));
}

}  // namespace omnitune
