#pragma once
// The automatic camera calibration's white and black reference regions on the panes (issue 12;
// config camera_auto.white_* and camera_auto.black_*, thesis ref. [31]): in editing mode
// (Camera > Edit reference regions, K) both rectangles are drawn, labelled, and the left button
// moves one (press inside it) or resizes it (press on or just outside a corner). Each drag is
// one undo step in the window's stack (ConfigDocument); Escape or K ends the mode. The regions
// stay inside the frame (geometry.image_width / image_height) and at least one pixel wide.
#include "core/Config.h"
#include "widgets/ConfigDrag.h"

#include <QObject>
#include <QPointF>
#include <QRect>

#include <vector>

class QAction;
class QMenu;
class QPainter;

namespace omnitune {

class ConfigDocument;
class ImageView;
class PipelineView;

class ReferenceRegionEditor : public QObject {
    Q_OBJECT
public:
    // How near (widget px) a press must be to a corner to resize from it.
    static constexpr double kGrabDistance = 8.0;

    enum class Region { None, White, Black };

    ReferenceRegionEditor(ConfigDocument* doc, PipelineView* view, QObject* parent = nullptr);

    bool isEditing() const { return editing_; }
    void setEditing(bool on);
    void fillMenu(QMenu* menu);
    // The region as the config holds it (image px).
    QRect region(Region which) const;

signals:
    void editingChanged(bool on);
    void message(const QString& text);  // for the status bar

private:
    // Which corners a drag moves: both for a move, one of each axis for a resize.
    struct Grab {
        Region region = Region::None;
        bool left = false, top = false, right = false, bottom = false;
    };
    Grab grabAt(QPointF p) const;
    void onPressed(QPointF p);
    void onDragged(QPointF p);
    void onReleased(QPointF p);
    Config dragged(QPointF p) const;  // the start config with the grabbed region moved by the drag
    QString regionName(Region which) const;
    void paintRegions(QPainter& p, const ImageView& pane) const;
    void updateSketches();

    ConfigDocument* doc_;
    PipelineView* view_;
    QAction* modeAction_ = nullptr;
    bool editing_ = false;
    Grab grab_;
    ConfigDrag drag_;
    QPointF pressed_;  // image px of the press
    std::vector<QWidget*> sketches_;
};

}  // namespace omnitune
