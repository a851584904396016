#include "widgets/ReferenceRegionEditor.h"

#include "widgets/ConfigDocument.h"
#include "widgets/ImageView.h"
#include "widgets/PaneEditMode.h"
#include "widgets/PaneSketch.h"
#include "widgets/PipelineView.h"

#include <QAction>
#include <QMenu>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

// The config's fields of one region.
struct RegionFields {
    int* x;
    int* y;
    int* width;
    int* height;
};

RegionFields fields(Config& c, ReferenceRegionEditor::Region which)
{
    CameraAutoOptions& o = c.cameraAuto;
    if (which == ReferenceRegionEditor::Region::White) return {&o.whiteX, &o.whiteY, &o.whiteWidth, &o.whiteHeight};
    return {&o.blackX, &o.blackY, &o.blackWidth, &o.blackHeight};
}

QRect regionOf(const Config& c, ReferenceRegionEditor::Region which)
{
    const CameraAutoOptions& o = c.cameraAuto;
    if (which == ReferenceRegionEditor::Region::White) return {o.whiteX, o.whiteY, o.whiteWidth, o.whiteHeight};
    return {o.blackX, o.blackY, o.blackWidth, o.blackHeight};
}

// One edge pair of a region dragged: `low` and `high` are the region's first and one-past-last
// pixel, moved by `d` where grabbed, kept inside 0..size and at least one pixel apart.
void dragEdges(int& low, int& high, bool moveLow, bool moveHigh, int d, int size)
{
    if (moveLow && moveHigh) {  // a move keeps the extent
        d = std::clamp(d, -low, size - high);
        low += d, high += d;
    } else if (moveLow) {
        low = std::clamp(low + d, 0, high - 1);
    } else if (moveHigh) {
        high = std::clamp(high + d, low + 1, size);
    }
}

}  // namespace

ReferenceRegionEditor::ReferenceRegionEditor(ConfigDocument* doc, PipelineView* view, QObject* parent)
    : QObject(parent), doc_(doc), view_(view), drag_(doc)
{
    connectPaneInput(view_, this, &ReferenceRegionEditor::onPressed, &ReferenceRegionEditor::onDragged,
                     &ReferenceRegionEditor::onReleased);
    connect(doc_, &ConfigDocument::changed, this, [this] { updateSketches(); });  // undo, the panel
    for (int i = 0; i < PipelineView::kPaneCount; ++i)
        sketches_.push_back(new PaneSketch(view_->pane(i), [this](QPainter& p, const ImageView& v) { paintRegions(p, v); }));
}

void ReferenceRegionEditor::fillMenu(QMenu* menu)
{
    modeAction_ = addEditModeAction(menu, this, &ReferenceRegionEditor::setEditing, tr("Edit white and blac&k reference regions"),
                                    QStringLiteral("editReferenceRegions"), QKeySequence(Qt::Key_K),
                                    tr("Place the regions the automatic camera calibration reads: a white and a black card on "
                                       "the robot (camera_auto.white_*, camera_auto.black_*)"));
}

void ReferenceRegionEditor::setEditing(bool on)
{
    if (on == editing_) return;
    drag_.cancel();  // a drag cut short (Esc, K while dragging): back to where it began
    grab_ = {};
    editing_ = on;
    emit editingChanged(on);  // the other editors give the left button up first
    showEditMode(view_, this, on, modeAction_, sketches_);
    emit message(on ? tr("Reference regions: drag inside a region to move it, from a corner to resize it; K or Esc ends")
                    : tr("Reference region editing off"));
}

QRect ReferenceRegionEditor::region(Region which) const { return regionOf(doc_->config(), which); }

QString ReferenceRegionEditor::regionName(Region which) const
{
    return which == Region::White ? tr("White reference") : tr("Black reference");
}

ReferenceRegionEditor::Grab ReferenceRegionEditor::grabAt(QPointF p) const
{
    const double reach = kGrabDistance / std::max(1e-6, view_->paneScale());  // image px
    // The nearest corner within reach, of either region.
    Grab corner;
    double nearest = reach;
    for (Region which : {Region::White, Region::Black}) {
        const QRectF r(region(which));
        for (bool left : {true, false})
            for (bool top : {true, false}) {
                const double d = std::hypot(p.x() - (left ? r.left() : r.right()), p.y() - (top ? r.top() : r.bottom()));
                if (d <= nearest) nearest = d, corner = {which, left, top, !left, !top};
            }
    }
    // Inside a region: a move, unless the region is large enough on screen to have room for
    // its corners' handles inside too (a small one is resized from just outside its corners).
    for (Region which : {Region::White, Region::Black}) {
        const QRectF r(region(which));
        if (!r.contains(p)) continue;
        const bool roomy = std::min(r.width(), r.height()) >= 3 * reach;
        return roomy && corner.region == which ? corner : Grab{which, true, true, true, true};
    }
    return corner;
}

void ReferenceRegionEditor::onPressed(QPointF p)
{
    grab_ = grabAt(p);
    if (grab_.region == Region::None) {
        emit message(tr("Press inside a reference region to move it, on a corner to resize it"));
        return;
    }
    drag_.begin();
    pressed_ = p;
}

Config ReferenceRegionEditor::dragged(QPointF p) const
{
    Config c = drag_.start();
    const RegionFields f = fields(c, grab_.region);
    const int dx = int(std::lround(p.x() - pressed_.x())), dy = int(std::lround(p.y() - pressed_.y()));
    int right = *f.x + *f.width, bottom = *f.y + *f.height;
    dragEdges(*f.x, right, grab_.left, grab_.right, dx, c.geometry.imageWidth);
    dragEdges(*f.y, bottom, grab_.top, grab_.bottom, dy, c.geometry.imageHeight);
    *f.width = right - *f.x;
    *f.height = bottom - *f.y;
    return c;
}

void ReferenceRegionEditor::onDragged(QPointF p)
{
    if (grab_.region == Region::None) return;
    const Config next = dragged(p);
    if (regionOf(next, grab_.region) != region(grab_.region)) drag_.show(next);
}

void ReferenceRegionEditor::onReleased(QPointF p)
{
    if (grab_.region == Region::None) return;
    onDragged(p);
    const Grab was = grab_;
    grab_ = {};
    const bool move = was.left && was.right;
    const QString what = (move ? tr("Move %1 region") : tr("Resize %1 region")).arg(regionName(was.region).toLower());
    std::optional<QString> refused;
    if (!drag_.finish(what, &refused)) {
        if (refused) emit message(*refused);
        return;
    }
    const QRect r = region(was.region);
    emit message(tr("%1 region: %2 x %3 px at (%4, %5)").arg(regionName(was.region)).arg(r.width()).arg(r.height()).arg(r.x()).arg(r.y()));
}

void ReferenceRegionEditor::updateSketches()
{
    for (QWidget* w : sketches_) w->update();
}

// Each region outlined twice (dark and light, visible on any image), its corners and its name.
void ReferenceRegionEditor::paintRegions(QPainter& p, const ImageView& pane) const
{
    for (Region which : {Region::White, Region::Black}) {
        const QRectF r = region(which);
        const QRectF w(pane.toWidget(r.topLeft()), pane.toWidget(r.bottomRight()));
        const QColor fill = which == Region::White ? QColor(255, 255, 255) : QColor(0, 0, 0);
        const QColor edge = which == Region::White ? QColor(0, 0, 0) : QColor(255, 255, 255);
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(edge, 3));
        p.drawRect(w);
        p.setPen(QPen(QColor(255, 200, 0), 1));
        p.drawRect(w);
        p.setPen(QPen(edge, 1));
        p.setBrush(fill);
        for (const QPointF c : {w.topLeft(), w.topRight(), w.bottomLeft(), w.bottomRight()}) p.drawEllipse(c, 3, 3);
        const QString name = which == Region::White ? tr("white") : tr("black");
        const QRectF text = p.fontMetrics().boundingRect(name).adjusted(-3, -1, 3, 1);
        const QRectF label(w.right() + 6, w.center().y() - text.height() / 2, text.width(), text.height());
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(fill.red(), fill.green(), fill.blue(), 190));
        p.drawRect(label);
        p.setPen(edge);
        p.drawText(label, Qt::AlignCenter, name);
    }
    p.setBrush(Qt::NoBrush);
}

}  // namespace omnitune
