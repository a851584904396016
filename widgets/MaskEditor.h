#pragma once
// Painting the robot mask on the panes (issue 11). In editing mode (Camera > Edit mask, M) the
// left button paints on any pane with the chosen tool: a round brush that marks robot (never
// processed), an eraser that gives pixels back to the detector, a polygon (click the vertices;
// Enter, a double-click or a click on the first vertex closes it) and a flood fill; polygon
// and fill paint robot or processed as chosen. The mask is tinted on every pane (MaskTint).
// Each stroke, polygon or fill is one undo step in the window's stack (ConfigDocument);
// a stroke shows live while it is dragged. Escape drops an open polygon, then leaves the mode.
// The pixel work is calib/mask/MaskPaint; this class only turns gestures into it.
#include "core/Config.h"

#include <QObject>
#include <QPointF>

#include <vector>

class QAction;
class QActionGroup;
class QComboBox;
class QDoubleSpinBox;
class QMenu;
class QPainter;
class QToolBar;

namespace omnitune {

class ConfigDocument;
class ImageView;
class PipelineView;

class MaskEditor : public QObject {
    Q_OBJECT
public:
    enum class Tool { Brush, Eraser, Polygon, Fill };
    // Brush radius bounds and step (image px): [ and ] or Ctrl+wheel change it by one step.
    static constexpr double kMinRadius = 0.5;
    static constexpr double kMaxRadius = 100.0;
    static constexpr double kRadiusStep = 1.0;
    // How near (widget px) a click must be to the first vertex to close the polygon.
    static constexpr double kCloseDistance = 8.0;
    // The mask image a config without one gets, beside config.yml.
    static constexpr const char* kDefaultMaskFile = "mask.png";

    MaskEditor(ConfigDocument* doc, PipelineView* view, QObject* parent = nullptr);

    bool isEditing() const { return editing_; }
    void setEditing(bool on);
    Tool tool() const { return tool_; }
    void setTool(Tool tool);
    double brushRadius() const { return radius_; }
    void setBrushRadius(double radius);
    // What a polygon or a fill paints: robot (true) or processed (false).
    bool areasAsRobot() const { return areasAsRobot_; }
    void setAreasAsRobot(bool robot);
    // The open polygon's vertices (image px).
    const std::vector<QPointF>& polygon() const { return polygon_; }
    // Fills the open polygon as one undo step; false when it has fewer than three vertices.
    bool closePolygon();
    // Escape: an open polygon is dropped first, then the mode ends.
    void escape();

    // The Camera menu's entries: the mode (M) and the tools with their keys.
    void fillMenu(QMenu* menu);
    // The tools, the brush size and what areas paint; shown while editing.
    QToolBar* toolBar() const { return toolBar_; }

signals:
    void editingChanged(bool on);
    void message(const QString& text);  // for the status bar

protected:
    // On the panes: Ctrl+wheel sizes the brush, a double-click closes the polygon.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void buildToolBar();
    void onPressed(QPointF p);
    void onDragged(QPointF p);
    void onReleased(QPointF p);
    // The config's mask to paint on: a copy (never the buffer the config, the undo stack and
    // the runner share), or a new all-processed one of the image size.
    cv::Mat maskCopy() const;
    // `mask` into the config as one undo step named `what`; nothing when no pixel changed.
    void commit(const cv::Mat& mask, int changed, const QString& what);
    Config withMask(const Config& from, const cv::Mat& mask) const;
    void updatePreviews();
    void paintPreview(QPainter& p, const ImageView& pane) const;
    QString toolHelp() const;

    ConfigDocument* doc_;
    PipelineView* view_;
    bool editing_ = false;
    Tool tool_ = Tool::Brush;
    double radius_ = 5.0;
    bool areasAsRobot_ = true;
    std::vector<QPointF> polygon_;
    QPointF cursor_{-1, -1};  // image px under the mouse, negative when outside the panes

    // A stroke being dragged.
    bool stroking_ = false;
    Config start_;  // as the stroke began: the undo step goes from here
    cv::Mat stroke_;
    QPointF last_;
    int strokeChanged_ = 0;

    QAction* modeAction_ = nullptr;
    QActionGroup* tools_ = nullptr;
    QAction* closeAction_ = nullptr;
    std::vector<QAction*> editingActions_;  // enabled only while editing: their keys mean other things otherwise
    QToolBar* toolBar_ = nullptr;
    QDoubleSpinBox* radiusBox_ = nullptr;
    QComboBox* areasBox_ = nullptr;
    std::vector<QWidget*> previews_;
};

}  // namespace omnitune
