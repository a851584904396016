#pragma once
// Dragging the robot centre and the inner and outer radius on any pane, and nudging the centre
// at sub-pixel steps from the keyboard (issue 11). In editing mode (Camera > Edit centre and
// radii, G) the left button grabs the nearest handle: the centre cross, or the inner or outer
// circle; the panes follow the drag live and the release is one undo step. Alt+arrows move the
// centre by a quarter pixel, Alt+Shift+arrows by a whole one (plain arrows step frames).
#include "core/Config.h"
#include "widgets/ConfigDrag.h"

#include <QObject>
#include <QPointF>

class QAction;
class QMenu;

namespace omnitune {

class ConfigDocument;
class PipelineView;

class GeometryEditor : public QObject {
    Q_OBJECT
public:
    static constexpr double kFineStepPx = 0.25;
    static constexpr double kCoarseStepPx = 1.0;
    // How near (widget px) a press must be to a handle to grab it.
    static constexpr double kGrabDistance = 10.0;

    GeometryEditor(ConfigDocument* doc, PipelineView* view, QObject* parent = nullptr);

    bool isEditing() const { return editing_; }
    void setEditing(bool on);
    // Moves the centre by (dx, dy) image px: one undo step per key, merged while one key repeats.
    void nudge(double dx, double dy);
    // The Camera menu's entries: the mode (G) and the nudge keys.
    void fillMenu(QMenu* menu);

signals:
    void editingChanged(bool on);
    void message(const QString& text);  // for the status bar

private:
    enum class Handle { None, Centre, Inner, Outer };
    void onPressed(QPointF p);
    void onDragged(QPointF p);
    void onReleased(QPointF p);
    Config dragged(Handle handle, QPointF p) const;  // the drag's start config with `handle` at `p`

    ConfigDocument* doc_;
    PipelineView* view_;
    QAction* modeAction_ = nullptr;
    bool editing_ = false;
    Handle grabbed_ = Handle::None;
    ConfigDrag drag_;     // live while it moves, one undo step from where it began
    QPointF grabOffset_;  // centre minus press point, so the centre does not jump to the cursor
};

}  // namespace omnitune
