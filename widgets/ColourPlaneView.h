#pragma once
// The H-S plane of the frame on screen with the colour boxes on it, and a V histogram below
// (issue 10). The plane shows how many processed pixels have each hue (across, 0..179) and
// saturation (up, 0..255); every enabled class's boxes are outlined in the class's display
// colour, the selected box thicker, with handles. Dragging the selected box moves its H and S
// ranges (hue wraps through 0), dragging one of its edges moves that bound; on the V strip its
// V min and max lines drag. Reports edits like ColourBoxEditor: live while dragging, finished
// on release, so a drag is one undo step.
#include "core/ColourClasses.h"

#include <QImage>
#include <QWidget>

#include <array>

namespace omnitune {

class ColourPlaneView : public QWidget {
    Q_OBJECT
public:
    explicit ColourPlaneView(QWidget* parent = nullptr);

    // The picture of the H-S plane (calib/colour/hsPlaneImage, 180 x 256) and the V counts.
    void setHistogram(const QImage& plane, const std::array<int, 256>& v);
    // The classes drawn and the selected box (class list position, box index; -1: none).
    void setClasses(const ColourClasses& classes, int selectedClass, int selectedBox);

    QSize sizeHint() const override { return {260, 300}; }
    // Where a hue / saturation / value lands in the widget, and back (tests drive the mouse).
    QPointF planePoint(int h, int s) const;
    double vX(int v) const;

signals:
    void edited(const omnitune::HsvRange& box, bool finished);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    enum class Grip { None, Move, HMin, HMax, SMin, SMax, VMin, VMax };
    QRectF planeRect() const;
    QRectF vRect() const;
    const HsvRange* selected() const;
    Grip gripAt(QPointF p) const;
    HsvRange dragged(QPointF p) const;
    int hueAt(double x) const;
    int satAt(double y) const;
    int valueAt(double x) const;

    QImage plane_;
    std::array<int, 256> v_{};
    ColourClasses classes_;
    int class_ = -1;
    int box_ = -1;
    Grip grip_ = Grip::None;
    QPointF pressAt_;
    HsvRange start_;
};

}  // namespace omnitune
