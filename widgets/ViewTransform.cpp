#include "widgets/ViewTransform.h"

#include <algorithm>

namespace omnitune {

double ViewTransform::scaleFor(QSize pane, QSize image) const
{
    if (!fit_ || image.isEmpty()) return zoom_;
    return std::min(double(pane.width()) / image.width(), double(pane.height()) / image.height());
}

void ViewTransform::fit()
{
    fit_ = true;
    emit changed();
}

void ViewTransform::setZoom(double zoom, QPointF center)
{
    fit_ = false;
    zoom_ = std::clamp(zoom, 0.05, 40.0);
    center_ = center;
    emit changed();
}

void ViewTransform::zoomBy(double factor, QPointF anchorImage, QSize pane, QSize image)
{
    const double scale = scaleFor(pane, image);
    const QPointF c = fit_ ? QPointF(image.width() / 2.0, image.height() / 2.0) : center_;
    const double next = std::clamp(scale * factor, 0.05, 40.0);
    // Keep the image point under the cursor where it is on screen.
    setZoom(next, anchorImage + (c - anchorImage) * (scale / next));
}

void ViewTransform::panBy(QPointF deltaImage)
{
    if (fit_) return;
    center_ -= deltaImage;
    emit changed();
}

void ViewTransform::centerOn(QPointF imagePoint)
{
    if (fit_) {
        fit_ = false;
        zoom_ = std::max(zoom_, 2.0);
    }
    center_ = imagePoint;
    emit changed();
}

}  // namespace omnitune
