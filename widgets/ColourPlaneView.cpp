#include "widgets/ColourPlaneView.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

constexpr double kGrip = 5.0;      // widget px around an edge that grabs it
constexpr double kVStrip = 44.0;   // height of the V histogram
constexpr double kMargin = 4.0;

int wrap180(int h) { return ((h % 180) + 180) % 180; }

}  // namespace

ColourPlaneView::ColourPlaneView(QWidget* parent) : QWidget(parent)
{
    setMinimumSize(200, 220);
    setMouseTracking(true);  // the cursor says what a press would grab
    setToolTip(tr("Hue across (0..179: red, yellow, green, cyan, blue, magenta), saturation up, brightness = how "
                  "many pixels of the frame have that colour. Drag the selected box (thick) or its edges; below, "
                  "the V histogram with the selected box's V range"));
}

void ColourPlaneView::setHistogram(const QImage& plane, const std::array<int, 256>& v)
{
    plane_ = plane;
    v_ = v;
    update();
}

void ColourPlaneView::setClasses(const ColourClasses& classes, int selectedClass, int selectedBox)
{
    classes_ = classes;
    class_ = selectedClass;
    box_ = selectedBox;
    update();
}

QRectF ColourPlaneView::planeRect() const
{
    return QRectF(kMargin, kMargin, width() - 2 * kMargin, height() - kVStrip - 3 * kMargin);
}

QRectF ColourPlaneView::vRect() const
{
    return QRectF(kMargin, height() - kVStrip - kMargin, width() - 2 * kMargin, kVStrip);
}

QPointF ColourPlaneView::planePoint(int h, int s) const
{
    const QRectF r = planeRect();
    return {r.left() + (h + 0.5) * r.width() / 180.0, r.bottom() - (s + 0.5) * r.height() / 256.0};
}

double ColourPlaneView::vX(int v) const
{
    const QRectF r = vRect();
    return r.left() + (v + 0.5) * r.width() / 256.0;
}

int ColourPlaneView::hueAt(double x) const
{
    const QRectF r = planeRect();
    return int(std::floor((x - r.left()) * 180.0 / r.width()));
}

int ColourPlaneView::satAt(double y) const
{
    const QRectF r = planeRect();
    return std::clamp(int(std::floor((r.bottom() - y) * 256.0 / r.height())), 0, 255);
}

int ColourPlaneView::valueAt(double x) const
{
    const QRectF r = vRect();
    return std::clamp(int(std::floor((x - r.left()) * 256.0 / r.width())), 0, 255);
}

const HsvRange* ColourPlaneView::selected() const
{
    if (class_ < 0 || class_ >= int(classes_.size())) return nullptr;
    const auto& boxes = classes_[std::size_t(class_)].boxes;
    return box_ >= 0 && box_ < int(boxes.size()) ? &boxes[std::size_t(box_)] : nullptr;
}

void ColourPlaneView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    const QRectF pr = planeRect();
    const QRectF vr = vRect();
    p.fillRect(pr, Qt::black);
    if (!plane_.isNull()) p.drawImage(pr, plane_);
    // One rectangle per box, two when its hue wraps through 0.
    auto hsRects = [&](const HsvRange& b) {
        std::vector<QRectF> out;
        const double top = planePoint(0, b.sMax).y() - pr.height() / 512.0;
        const double bottom = planePoint(0, b.sMin).y() + pr.height() / 512.0;
        auto span = [&](int h0, int h1) {
            out.emplace_back(QPointF(planePoint(h0, 0).x() - pr.width() / 360.0, top),
                             QPointF(planePoint(h1, 0).x() + pr.width() / 360.0, bottom));
        };
        if (b.hMin <= b.hMax) span(b.hMin, b.hMax);
        else {
            span(b.hMin, 179);
            span(0, b.hMax);
        }
        return out;
    };
    p.setRenderHint(QPainter::Antialiasing, false);
    for (int c = 0; c < int(classes_.size()); ++c) {
        const ColourClassDef& def = classes_[std::size_t(c)];
        if (!def.enabled) continue;
        const QColor colour(def.display[2], def.display[1], def.display[0]);
        for (int i = 0; i < int(def.boxes.size()); ++i) {
            const HsvRange& b = def.boxes[std::size_t(i)];
            if (!b.enabled) continue;
            const bool sel = c == class_ && i == box_;
            for (const QRectF& r : hsRects(b)) {
                p.setPen(QPen(sel ? Qt::white : colour, sel ? 2.5 : 1.2, sel ? Qt::SolidLine : Qt::DashLine));
                p.setBrush(Qt::NoBrush);
                p.drawRect(r);
            }
        }
    }
    // Axes, in words: the plane has no room for tick labels.
    p.setPen(QColor(220, 220, 220));
    p.drawText(pr.adjusted(3, 1, -3, -1), Qt::AlignBottom | Qt::AlignRight, tr("H 0..179 →"));
    p.drawText(pr.adjusted(3, 1, -3, -1), Qt::AlignTop | Qt::AlignRight, tr("S ↑ 255"));
    // The V histogram, log scaled, and the selected box's V range.
    p.fillRect(vr, QColor(30, 30, 30));
    const int top = *std::max_element(v_.begin(), v_.end());
    if (top > 0) {
        p.setPen(QColor(200, 200, 200));
        for (int v = 0; v < 256; ++v) {
            if (v_[std::size_t(v)] == 0) continue;
            const double h = vr.height() * std::log1p(v_[std::size_t(v)]) / std::log1p(top);
            p.drawLine(QPointF(vX(v), vr.bottom()), QPointF(vX(v), vr.bottom() - h));
        }
    }
    if (const HsvRange* b = selected(); b && b->enabled) {
        p.fillRect(QRectF(QPointF(vX(b->vMin), vr.top()), QPointF(vX(b->vMax), vr.bottom())), QColor(255, 255, 255, 50));
        p.setPen(QPen(Qt::white, 2));
        p.drawLine(QPointF(vX(b->vMin), vr.top()), QPointF(vX(b->vMin), vr.bottom()));
        p.drawLine(QPointF(vX(b->vMax), vr.top()), QPointF(vX(b->vMax), vr.bottom()));
    }
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(vr.adjusted(2, 0, 0, 0), Qt::AlignTop | Qt::AlignLeft, tr("V"));
}

ColourPlaneView::Grip ColourPlaneView::gripAt(QPointF p) const
{
    const HsvRange* b = selected();
    if (!b || !b->enabled) return Grip::None;
    if (vRect().adjusted(-kGrip, -kGrip, kGrip, kGrip).contains(p)) {
        const double dMin = std::abs(p.x() - vX(b->vMin));
        const double dMax = std::abs(p.x() - vX(b->vMax));
        if (std::min(dMin, dMax) > kGrip) return Grip::None;
        return dMin < dMax ? Grip::VMin : Grip::VMax;
    }
    const QRectF pr = planeRect();
    if (!pr.adjusted(-kGrip, -kGrip, kGrip, kGrip).contains(p)) return Grip::None;
    const int h = wrap180(hueAt(p.x()));
    const int s = satAt(p.y());
    const bool inS = s >= b->sMin - 3 && s <= b->sMax + 3;
    const bool inH = b->containsHue(h);
    auto near = [&](double a, double x) { return std::abs(a - x) <= kGrip; };
    if (inS && near(p.x(), planePoint(b->hMin, 0).x() - pr.width() / 360.0)) return Grip::HMin;
    if (inS && near(p.x(), planePoint(b->hMax, 0).x() + pr.width() / 360.0)) return Grip::HMax;
    if (inH && near(p.y(), planePoint(0, b->sMax).y())) return Grip::SMax;
    if (inH && near(p.y(), planePoint(0, b->sMin).y())) return Grip::SMin;
    if (inH && s >= b->sMin && s <= b->sMax) return Grip::Move;
    return Grip::None;
}

HsvRange ColourPlaneView::dragged(QPointF p) const
{
    HsvRange b = start_;
    const int h = std::clamp(hueAt(p.x()), 0, 179);
    const int s = satAt(p.y());
    switch (grip_) {
    case Grip::Move: {
        const int dh = hueAt(p.x()) - hueAt(pressAt_.x());
        const int ds = std::clamp(s - satAt(pressAt_.y()), -start_.sMin, 255 - start_.sMax);
        const bool full = start_.hMin == 0 && start_.hMax == 179;
        if (!full) {
            b.hMin = wrap180(start_.hMin + dh);
            b.hMax = wrap180(start_.hMax + dh);
        }
        b.sMin = start_.sMin + ds;
        b.sMax = start_.sMax + ds;
        break;
    }
    case Grip::HMin: b.hMin = h; break;
    case Grip::HMax: b.hMax = h; break;
    case Grip::SMin: b.sMin = std::min(s, b.sMax); break;
    case Grip::SMax: b.sMax = std::max(s, b.sMin); break;
    case Grip::VMin: b.vMin = std::min(valueAt(p.x()), b.vMax); break;
    case Grip::VMax: b.vMax = std::max(valueAt(p.x()), b.vMin); break;
    case Grip::None: break;
    }
    return b;
}

void ColourPlaneView::mousePressEvent(QMouseEvent* event)
{
    grip_ = event->button() == Qt::LeftButton ? gripAt(event->localPos()) : Grip::None;
    if (grip_ == Grip::None) return;
    pressAt_ = event->localPos();
    start_ = *selected();
}

void ColourPlaneView::mouseMoveEvent(QMouseEvent* event)
{
    if (grip_ == Grip::None) {
        const Grip g = gripAt(event->localPos());
        setCursor(g == Grip::Move ? Qt::SizeAllCursor
                  : g == Grip::None ? Qt::ArrowCursor
                  : (g == Grip::SMin || g == Grip::SMax) ? Qt::SizeVerCursor : Qt::SizeHorCursor);
        return;
    }
    emit edited(dragged(event->localPos()), false);
}

void ColourPlaneView::mouseReleaseEvent(QMouseEvent* event)
{
    if (grip_ == Grip::None || event->button() != Qt::LeftButton) return;
    const HsvRange b = dragged(event->localPos());
    grip_ = Grip::None;
    emit edited(b, true);
}

}  // namespace omnitune
