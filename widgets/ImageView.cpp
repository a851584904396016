#include "widgets/ImageView.h"

#include "core/BallModel.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>

namespace omnitune {

QImage toQImage(const cv::Mat& mat)
{
    if (mat.empty()) return {};
    if (mat.type() == CV_8UC3)
        return QImage(mat.data, mat.cols, mat.rows, int(mat.step), QImage::Format_BGR888).copy();
    if (mat.type() == CV_8UC1)
        return QImage(mat.data, mat.cols, mat.rows, int(mat.step), QImage::Format_Grayscale8).copy();
    return {};
}

ImageView::ImageView(const QString& title, ViewTransform* transform, const OverlayOptions* overlays, QWidget* parent)
    : QWidget(parent), title_(title), transform_(transform), overlays_(overlays)
{
    setMouseTracking(true);
    setMinimumSize(160, 120);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setObjectName(title);
    connect(transform_, &ViewTransform::changed, this, qOverload<>(&QWidget::update));
}

void ImageView::setImage(const QImage& image)
{
    image_ = image;
    update();
}

void ImageView::setOverlay(std::shared_ptr<const OverlayData> overlay)
{
    overlay_ = std::move(overlay);
    update();
}

void ImageView::setTruth(const TruthOverlay& truth)
{
    truth_ = truth;
    update();
}

void ImageView::setMarking(bool on)
{
    marking_ = on;
    markDown_ = false;
    setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
    update();
}

double ImageView::scale() const { return transform_->scaleFor(size(), image_.size()); }

QPointF ImageView::imageCenter() const
{
    return transform_->isFit() ? QPointF(image_.width() / 2.0, image_.height() / 2.0) : transform_->center();
}

QPointF ImageView::toImage(QPointF w) const
{
    return (w - QPointF(width() / 2.0, height() / 2.0)) / scale() + imageCenter();
}

QPointF ImageView::toWidget(QPointF i) const
{
    return (i - imageCenter()) * scale() + QPointF(width() / 2.0, height() / 2.0);
}

void ImageView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 30, 30));
    if (!image_.isNull()) {
        const QRectF target(toWidget(QPointF(0, 0)), toWidget(QPointF(image_.width(), image_.height())));
        p.setRenderHint(QPainter::SmoothPixmapTransform, scale() < 1.0);
        p.drawImage(target, image_);
        paintOverlay(p);
        paintTruth(p);
    } else {
        p.setPen(Qt::gray);
        p.drawText(rect(), Qt::AlignCenter, tr("no image"));
    }
    // Title in the top-left corner, readable over any image.
    const QFontMetrics fm(font());
    const QRect box(4, 4, fm.horizontalAdvance(title_) + 10, fm.height() + 4);
    p.fillRect(box, QColor(0, 0, 0, 170));
    p.setPen(Qt::white);
    p.drawText(box, Qt::AlignCenter, title_);
}

void ImageView::paintOverlay(QPainter& p) const
{
    if (!overlay_) return;
    p.setRenderHint(QPainter::Antialiasing, true);
    const Config& c = overlay_->config;
    const QPointF centre(c.geometry.centerX, c.geometry.centerY);
    const double s = scale();
    auto circle = [&](QPointF imageCentre, double radius) {
        p.drawEllipse(toWidget(imageCentre), radius * s, radius * s);
    };
    if (overlays_->geometry) {
        p.setPen(QPen(QColor(255, 255, 0, 200), 1));
        circle(centre, c.geometry.innerRadius);
        circle(centre, c.geometry.outerRadius);
        const QPointF w = toWidget(centre);
        p.drawLine(w - QPointF(6, 0), w + QPointF(6, 0));
        p.drawLine(w - QPointF(0, 6), w + QPointF(0, 6));
        if (overlay_->maskOutline) {
            p.setPen(QPen(QColor(255, 160, 0, 220), 1));
            for (const auto& line : *overlay_->maskOutline) {
                QPolygonF poly;
                for (const cv::Point& q : line) poly << toWidget(QPointF(q.x + 0.5, q.y + 0.5));
                p.drawPolygon(poly);
            }
        }
    }
    if (overlays_->areas) {
        p.setPen(QPen(QColor(0, 200, 255, 160), 1, Qt::DashLine));
        for (double b : c.hough.areaBounds) circle(centre, b);
    }
    if (overlays_->sensors) {
        p.setPen(QPen(QColor(255, 255, 255, 90), 1));
        for (int i = 0; i < c.sensors.count; ++i) {
            const double a = 2.0 * M_PI * i / c.sensors.count;
            const QPointF dir(std::cos(a), -std::sin(a));
            p.drawLine(toWidget(centre + dir * c.sensors.innerRadius), toWidget(centre + dir * c.sensors.outerRadius));
        }
    }
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.8));
    p.setFont(small);
    if (overlays_->candidates) {
        for (const BallCandidate& k : overlay_->candidates) {
            const bool ok = k.rejected == RejectReason::None;
            p.setPen(QPen(ok ? QColor(0, 255, 0) : QColor(255, 90, 60), ok ? 2 : 1));
            circle(QPointF(k.x, k.y), std::max(k.radiusPx, 2.0));
            const QString label = QStringLiteral("%1 %2/%3/%4")
                                      .arg(k.area >= 0 ? QStringLiteral("A%1").arg(k.area + 1) : QStringLiteral("cv"))
                                      .arg(k.scores.nonGreenPct, 0, 'f', 0)
                                      .arg(k.scores.nonBlackPct, 0, 'f', 0)
                                      .arg(k.scores.circularityPct, 0, 'f', 0);
            p.drawText(toWidget(QPointF(k.x + k.radiusPx, k.y - k.radiusPx)) + QPointF(3, -2), label);
        }
    }
    if (overlays_->ball && overlay_->detection.found) {
        const BallDetection& d = overlay_->detection;
        p.setPen(QPen(QColor(0, 255, 0), 3));
        circle(QPointF(d.px, d.py), d.radiusPx + 2);
        const QString label = QStringLiteral("ball  x %1 m  y %2 m").arg(d.xM, 0, 'f', 2).arg(d.yM, 0, 'f', 2);
        const QPointF at = toWidget(QPointF(d.px, d.py + d.radiusPx)) + QPointF(-20, 16);
        p.fillRect(QRectF(at + QPointF(-2, -12), QSizeF(p.fontMetrics().horizontalAdvance(label) + 4, 16)),
                   QColor(0, 0, 0, 170));
        p.setPen(QColor(0, 255, 0));
        p.drawText(at, label);
    }
    if (overlays_->cursorRadius && cursor_.x() >= 0) {
        const double d = std::hypot(cursor_.x() - centre.x(), cursor_.y() - centre.y());
        p.setPen(QPen(QColor(255, 255, 255, 200), 1, Qt::DotLine));
        circle(cursor_, BallModel(c.ball).radiusAt(d));
    }
}

void ImageView::paintTruth(QPainter& p) const
{
    if (!overlays_->truth && !truth_.marking) return;
    QString label;
    const QColor colour(255, 60, 255);
    if (truth_.state == TruthOverlay::Ball) {
        p.setRenderHint(QPainter::Antialiasing, true);
        p.setPen(QPen(colour, 2, Qt::DashLine));
        const double s = scale();
        p.drawEllipse(toWidget(QPointF(truth_.x, truth_.y)), truth_.radius * s, truth_.radius * s);
        const QPointF w = toWidget(QPointF(truth_.x, truth_.y));
        p.drawLine(w - QPointF(4, 0), w + QPointF(4, 0));
        p.drawLine(w - QPointF(0, 4), w + QPointF(0, 4));
        label = tr("truth: ball");
    } else if (truth_.state == TruthOverlay::NoBall) {
        label = tr("truth: no ball");
    } else if (truth_.marking) {
        label = tr("truth: not marked");
    }
    if (label.isEmpty()) return;
    // Top-right corner, away from the title.
    const QFontMetrics fm(font());
    const QRect box(width() - fm.horizontalAdvance(label) - 14, 4, fm.horizontalAdvance(label) + 10, fm.height() + 4);
    p.fillRect(box, QColor(0, 0, 0, 170));
    p.setPen(colour);
    p.drawText(box, Qt::AlignCenter, label);
}

void ImageView::wheelEvent(QWheelEvent* event)
{
    if (image_.isNull()) return;
    const double factor = std::pow(1.0015, event->angleDelta().y());
    transform_->zoomBy(factor, toImage(event->position()), size(), image_.size());
}

void ImageView::mousePressEvent(QMouseEvent* event)
{
    if (marking_ && event->button() == Qt::LeftButton && !image_.isNull()) {
        markDown_ = true;
        emit markPressed(toImage(event->localPos()));
        return;
    }
    // The middle button always pans; the left one unless it marks.
    if (event->button() != Qt::MiddleButton && (marking_ || event->button() != Qt::LeftButton)) return;
    dragging_ = true;
    dragStart_ = event->localPos();
}

void ImageView::mouseMoveEvent(QMouseEvent* event)
{
    if (markDown_) emit markDragged(toImage(event->localPos()));
    if (dragging_ && !transform_->isFit()) {
        transform_->panBy((event->localPos() - dragStart_) / scale());
        dragStart_ = event->localPos();
    }
    cursor_ = toImage(event->localPos());
    emit hovered(cursor_);
    if (overlays_->cursorRadius) update();
}

void ImageView::mouseReleaseEvent(QMouseEvent* event)
{
    if (markDown_ && event->button() == Qt::LeftButton) {
        markDown_ = false;
        emit markReleased(toImage(event->localPos()));
        return;
    }
    dragging_ = false;
}

void ImageView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (marking_ && event->button() == Qt::LeftButton) {
        mousePressEvent(event);  // two quick marks, not an enlarged pane
        return;
    }
    emit doubleClicked();
}

void ImageView::leaveEvent(QEvent*)
{
    cursor_ = QPointF(-1, -1);
    update();
    emit left();
}

}  // namespace omnitune
