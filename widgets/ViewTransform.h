#pragma once
// The zoom and pan every image pane shares: one image point at the pane's centre and a scale.
// "Fit" recomputes the scale from the pane size, so all panes show the whole image.
#include <QObject>
#include <QPointF>
#include <QSize>

namespace omnitune {

class ViewTransform : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    bool isFit() const { return fit_; }
    double zoom() const { return zoom_; }   // screen px per image px (when not fit)
    QPointF center() const { return center_; }  // image point shown at the pane centre

    // The scale a pane of `pane` size uses for an image of `image` size.
    double scaleFor(QSize pane, QSize image) const;

    void fit();
    void setZoom(double zoom, QPointF center);
    void zoomBy(double factor, QPointF anchorImage, QSize pane, QSize image);
    void panBy(QPointF deltaImage);
    void centerOn(QPointF imagePoint);

signals:
    void changed();

private:
    bool fit_ = true;
    double zoom_ = 1.0;
    QPointF center_;
};

}  // namespace omnitune
