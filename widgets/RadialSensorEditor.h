#pragma once
// The radial sensors on the panes (issue 11). In editing mode (Camera > Edit radial sensors, R)
// every ray is drawn with its two ends; the left button drags an end of any ray (all rays
// start and end at the same radii, so the inner or the outer radius follows) or, grabbed in
// the middle, turns all rays (the angular offset). A click on a ray selects it: the RayStrip
// under the panes shows the colour classes along it for the frame on screen. Each drag is one
// undo step; count, radii and offset are also in the threshold panel (sensors.*).
#include "core/Config.h"
#include "widgets/ConfigDrag.h"

#include <QObject>
#include <QPointF>

#include <memory>

class QAction;
class QMenu;
class QPainter;

namespace omnitune {

class ConfigDocument;
class ImageView;
class PipelineView;
class RayStrip;
struct PipelineRun;

class RadialSensorEditor : public QObject {
    Q_OBJECT
public:
    // How near (widget px) a press must be to a ray, or along it to an end, to grab it.
    static constexpr double kGrabDistance = 10.0;
    static constexpr double kRadiusStep = 0.5;  // px the dragged radii snap to
    static constexpr double kAngleStep = 0.1;   // degrees the dragged offset snaps to

    RadialSensorEditor(ConfigDocument* doc, PipelineView* view, RayStrip* strip, QObject* parent = nullptr);

    bool isEditing() const { return editing_; }
    void setEditing(bool on);
    int selectedRay() const { return selected_; }
    void selectRay(int ray);
    // The run on screen: the strip reads the selected ray's classes from it.
    void setRun(std::shared_ptr<const PipelineRun> run);
    void fillMenu(QMenu* menu);

signals:
    void editingChanged(bool on);
    void message(const QString& text);  // for the status bar

private:
    enum class Handle { None, Inner, Outer, Turn };
    struct Grab {
        Handle handle = Handle::None;
        int ray = -1;
    };
    Grab grabAt(QPointF p) const;
    void onPressed(QPointF p);
    void onDragged(QPointF p);
    void onReleased(QPointF p);
    Config dragged(QPointF p) const;  // the start config with the grabbed handle at `p`
    double angleAt(QPointF p) const;  // degrees, counter-clockwise from image +x, around the centre
    void paintRays(QPainter& p, const ImageView& pane) const;
    void refreshStrip();
    void updateSketches();

    ConfigDocument* doc_;
    PipelineView* view_;
    RayStrip* strip_;
    std::shared_ptr<const PipelineRun> run_;
    QAction* modeAction_ = nullptr;
    bool editing_ = false;
    int selected_ = -1;
    Grab grab_;
    ConfigDrag drag_;       // live while the mouse moves, one undo step from the press on release
    double startAngle_ = 0; // degrees at the press, for turning
    std::vector<QWidget*> sketches_;
};

}  // namespace omnitune
