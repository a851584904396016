#pragma once
// One image pane: an image under the shared zoom/pan, a title, and the overlays. Wheel zooms
// at the cursor, a drag pans (all panes follow through the shared ViewTransform). In marking
// mode the left button marks (press, drag, release are reported in image px) and the middle
// button pans.
#include "widgets/Overlay.h"
#include "widgets/ViewTransform.h"

#include <QImage>
#include <QWidget>

#include <memory>
#include <vector>

namespace omnitune {

class ImageView : public QWidget {
    Q_OBJECT
public:
    ImageView(const QString& title, ViewTransform* transform, const OverlayOptions* overlays, QWidget* parent = nullptr);

    void setImage(const QImage& image);
    const QImage& image() const { return image_; }
    void setOverlay(std::shared_ptr<const OverlayData> overlay);
    void setTruth(const TruthOverlay& truth);
    void setMarking(bool on);
    QString title() const { return title_; }

    // Widget position <-> image position under the current transform.
    QPointF toImage(QPointF widgetPos) const;
    QPointF toWidget(QPointF imagePos) const;
    // The candidate whose label or circle is at this widget position (as last painted), or -1.
    // Its tooltip explains the label ("A3 98/100/96") in words.
    int candidateAt(QPointF widgetPos) const;
    // The label boxes of the last paint, in widget px: candidate index, or -1 for the ball.
    struct PlacedLabel {
        QRectF box;
        int candidate;
    };
    const std::vector<PlacedLabel>& placedLabels() const { return labels_; }

signals:
    void hovered(QPointF imagePos);
    void left();
    void doubleClicked();
    void markPressed(QPointF imagePos);
    void markDragged(QPointF imagePos);
    void markReleased(QPointF imagePos);

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

public:
    double scale() const;  // widget px per image px

private:
    QPointF imageCenter() const;
    void paintOverlay(QPainter& p) const;  // places the labels (labels_)
    void paintTruth(QPainter& p) const;
    void paintMove(QPainter& p, const BallCandidate& k, const QColor& colour) const;

    QString title_;
    ViewTransform* transform_;
    const OverlayOptions* overlays_;
    QImage image_;
    std::shared_ptr<const OverlayData> overlay_;
    QPointF dragStart_;
    bool dragging_ = false;
    bool marking_ = false;
    bool markDown_ = false;
    TruthOverlay truth_;
    QPointF cursor_{-1, -1};  // image position under the mouse, or negative
    mutable std::vector<PlacedLabel> labels_;  // where the last paint put the labels
};

// BGR (CV_8UC3) or grey (CV_8UC1) cv::Mat as a QImage (a deep copy).
QImage toQImage(const cv::Mat& mat);

}  // namespace omnitune
