#pragma once
// The window's editors that paint or drag on the panes beyond the geometry (issue 11): the
// mask editor, mask import, the radial sensor editor with its ray strip, the distance-map
// points (a panel the window docks) and the camera calibration's reference regions (issue 12),
// wired so that one
// of them, the geometry editor or truth marking holds the left button at a time. Keeps that
// wiring out of the main window, which only places the tool bar and the strip.
#include <QObject>

#include <memory>

class QMenu;
class QWidget;

namespace omnitune {

class ConfigDocument;
class DistancePointsPanel;
class GeometryEditor;
class MaskEditor;
class PipelineView;
class RadialSensorEditor;
class RayStrip;
class ReferenceRegionEditor;
class TruthMarker;
struct PipelineRun;

class PaneEditors : public QObject {
    Q_OBJECT
public:
    PaneEditors(ConfigDocument* doc, PipelineView* view, GeometryEditor* geometry, TruthMarker* marker, RayStrip* strip,
                QWidget* parent);

    MaskEditor* mask() const { return mask_; }
    RadialSensorEditor* sensors() const { return sensors_; }
    DistancePointsPanel* distances() const { return distances_; }
    ReferenceRegionEditor* referenceRegions() const { return references_; }
    // Camera menu: Edit mask (M), the mask tools, Import mask..., Edit radial sensors (R),
    // Edit reference regions (K).
    void fillMenu(QMenu* camera);
    // The run on screen: the ray strip's classes and the import preview's frame.
    void setRun(std::shared_ptr<const PipelineRun> run);
    // Every editor off (another source opens).
    void stopEditing();
    // Escape: an open polygon is dropped, then the editing ends.
    void escape();
    // Every holder here lets go (mask, sensors, distances, reference regions, geometry, truth
    // marking), because one outside (colour sampling) takes the left button.
    void releaseLeftButton();

signals:
    void message(const QString& text);  // for the status bar
    // One of the editors here took the panes' left button: holders outside (colour sampling)
    // let go of it.
    void leftButtonTaken();

private:
    // `on` from one holder of the left button turns every other one off.
    void exclusive(const QObject* from, bool on);
    void releaseAllBut(const QObject* keep);

    ConfigDocument* doc_;
    QWidget* parent_;
    GeometryEditor* geometry_;
    TruthMarker* marker_;
    MaskEditor* mask_;
    RadialSensorEditor* sensors_;
    DistancePointsPanel* distances_;
    ReferenceRegionEditor* references_;
    std::shared_ptr<const PipelineRun> run_;
};

}  // namespace omnitune
