#include "widgets/ImageView.h"

#include "core/BallModel.h"
#include "widgets/CandidateLabel.h"
#include "widgets/LabelPlacement.h"

#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
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
    labels_.clear();  // paintOverlay() places them again
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
        p.setPen(QPen(overlay_colour::geometry(), 1));
        circle(centre, c.geometry.innerRadius);
        circle(centre, c.geometry.outerRadius);
        const QPointF w = toWidget(centre);
        p.drawLine(w - QPointF(6, 0), w + QPointF(6, 0));
        p.drawLine(w - QPointF(0, 6), w + QPointF(0, 6));
        if (overlay_->maskTint && !image_.isNull()) {
            const QImage& tint = *overlay_->maskTint;
            p.drawImage(QRectF(toWidget(QPointF(0, 0)), toWidget(QPointF(tint.width(), tint.height()))), tint);
        }
        if (overlay_->maskOutline) {
            p.setPen(QPen(overlay_colour::maskOutline(), 1));
            for (const auto& line : *overlay_->maskOutline) {
                QPolygonF poly;
                for (const cv::Point& q : line) poly << toWidget(QPointF(q.x + 0.5, q.y + 0.5));
                p.drawPolygon(poly);
            }
        }
    }
    if (overlays_->areas) {
        p.setPen(QPen(overlay_colour::areas(), 1, Qt::DashLine));
        for (double b : c.hough.areaBounds) circle(centre, b);
    }
    if (overlays_->sensors) {
        p.setPen(QPen(overlay_colour::sensors(), 1));
        for (int i = 0; i < c.sensors.count; ++i) {
            const double a = radialSensorAngle(c.sensors, i);
            const QPointF dir(std::cos(a), -std::sin(a));
            p.drawLine(toWidget(centre + dir * c.sensors.innerRadius), toWidget(centre + dir * c.sensors.outerRadius));
        }
    }
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.8));
    p.setFont(small);
    const QFontMetricsF fm(small);
    // The labels are placed together so that crowded candidates near the robot stay readable:
    // the accepted ball's first, then the candidates in the pipeline's order.
    std::vector<LabelRequest> requests;
    std::vector<QString> texts;
    std::vector<int> owners;  // candidate index, -1 for the ball
    const BallDetection& d = overlay_->detection;
    const bool showBall = overlays_->ball && d.found;
    if (showBall) {
        texts.push_back(tr("ball  x %1 m  y %2 m").arg(d.xM, 0, 'f', 2).arg(d.yM, 0, 'f', 2));
        requests.push_back({toWidget(QPointF(d.px, d.py)), (d.radiusPx + 2) * s, QSizeF(fm.horizontalAdvance(texts.back()) + 6, fm.height() + 2)});
        owners.push_back(-1);
    }
    if (overlays_->candidates) {
        for (int i = 0; i < int(overlay_->candidates.size()); ++i) {
            const BallCandidate& k = overlay_->candidates[i];
            texts.push_back(candidateLabel(k));
            requests.push_back({toWidget(QPointF(k.x, k.y)), std::max(k.radiusPx, 2.0) * s,
                                QSizeF(fm.horizontalAdvance(texts.back()) + 4, fm.height())});
            owners.push_back(i);
        }
        for (const BallCandidate& k : overlay_->candidates) {
            const bool ok = k.rejected == RejectReason::None;
            const QColor colour = ok ? overlay_colour::accepted() : overlay_colour::rejected();
            p.setPen(QPen(colour, ok ? 2 : 1));
            circle(QPointF(k.x, k.y), std::max(k.radiusPx, 2.0));
            if (k.move != CandidateMove::None) paintMove(p, k, colour);
        }
    }
    if (showBall) {
        p.setPen(QPen(overlay_colour::accepted(), 3));
        circle(QPointF(d.px, d.py), d.radiusPx + 2);
    }
    // Below the pane's title and truth boxes. A label with no room left tries its area alone
    // ("A3"); the tooltip still gives the scores.
    const QRectF bounds = QRectF(rect()).adjusted(0, fontMetrics().height() + 8, 0, 0);
    std::vector<LabelSpot> spots = placeLabels(requests, bounds);
    std::vector<QRectF> placed;
    std::vector<std::size_t> crowded;
    for (std::size_t i = 0; i < spots.size(); ++i) {
        if (spots[i].placed)
            placed.push_back(spots[i].box);
        else if (owners[i] >= 0)
            crowded.push_back(i);
    }
    std::vector<LabelRequest> shortRequests;
    for (std::size_t i : crowded) {
        texts[i] = texts[i].section(QLatin1Char(' '), 0, 0);
        shortRequests.push_back({requests[i].centre, requests[i].radius, QSizeF(fm.horizontalAdvance(texts[i]) + 4, fm.height())});
    }
    const std::vector<LabelSpot> shortSpots = placeLabels(shortRequests, bounds, placed);
    for (std::size_t j = 0; j < crowded.size(); ++j) spots[crowded[j]] = shortSpots[j];
    for (std::size_t i = 0; i < spots.size(); ++i) {
        if (!spots[i].placed) continue;
        const QRectF& box = spots[i].box;
        const bool ball = owners[i] < 0;
        const QColor colour = ball || overlay_->candidates[owners[i]].rejected == RejectReason::None
                                  ? overlay_colour::accepted()
                                  : overlay_colour::rejected();
        if (spots[i].leader) {
            p.setPen(QPen(colour, 1, Qt::DotLine));
            const QPointF c = requests[i].centre;
            const QPointF end = nearestPoint(box, c);
            const QPointF dir = end - c;
            const double len = std::hypot(dir.x(), dir.y());
            if (len > requests[i].radius) p.drawLine(c + dir * (requests[i].radius / len), end);
        }
        p.fillRect(box, QColor(0, 0, 0, 190));  // readable over the carpet, the rings and a white pane
        p.setPen(colour);
        p.drawText(box, Qt::AlignCenter, texts[i]);
        labels_.push_back({box, owners[i]});
    }
    if (overlays_->cursorRadius && cursor_.x() >= 0) {
        const double d = std::hypot(cursor_.x() - centre.x(), cursor_.y() - centre.y());
        p.setPen(QPen(overlay_colour::cursor(), 1, Qt::DotLine));
        circle(cursor_, BallModel(c.ball).radiusAt(d));
    }
}

// A candidate a second look moved: a small cross where the search put it, dotted to its circle.
void ImageView::paintMove(QPainter& p, const BallCandidate& k, const QColor& colour) const
{
    const QPointF from = toWidget(QPointF(k.searchX, k.searchY));
    const QPointF to = toWidget(QPointF(k.x, k.y));
    p.setPen(QPen(colour, 1));
    p.drawLine(from - QPointF(3, 3), from + QPointF(3, 3));
    p.drawLine(from - QPointF(3, -3), from + QPointF(3, -3));
    const QPointF dir = to - from;
    const double len = std::hypot(dir.x(), dir.y());
    const double rim = std::max(k.radiusPx, 2.0) * scale();
    if (len <= rim) return;  // the search's centre is inside the circle: the cross says it all
    p.setPen(QPen(colour, 1, Qt::DotLine));
    p.drawLine(from, to - dir * (rim / len));
}

void ImageView::paintTruth(QPainter& p) const
{
    if (!overlays_->truth && !truth_.marking) return;
    QString label;
    const QColor colour = overlay_colour::truth();
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

int ImageView::candidateAt(QPointF widgetPos) const
{
    for (const PlacedLabel& l : labels_)
        if (l.candidate >= 0 && l.box.contains(widgetPos)) return l.candidate;
    if (!overlay_ || !overlays_->candidates) return -1;
    const QPointF at = toImage(widgetPos);
    int best = -1;
    double bestD = 0.0;
    for (int i = 0; i < int(overlay_->candidates.size()); ++i) {
        const BallCandidate& k = overlay_->candidates[i];
        const double dist = std::hypot(at.x() - k.x, at.y() - k.y);
        if (dist <= std::max(k.radiusPx, 2.0) + 2.0 / scale() && (best < 0 || dist < bestD)) {
            best = i;
            bestD = dist;
        }
    }
    return best;
}

bool ImageView::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        const int i = candidateAt(help->pos());
        if (i >= 0)
            QToolTip::showText(help->globalPos(), candidateExplanation(overlay_->candidates[i], overlay_->config.validation), this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
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
