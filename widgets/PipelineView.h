#pragma once
// The five stage panes of thesis Fig. 4.6 plus the Hough accumulator, side by side under one
// zoom/pan. Double-clicking a pane enlarges it; double-clicking again brings the others back.
// Everything on the panes belongs to one run: showing a run replaces images, overlays and
// captions together, and a source change clears them all until its first frame arrives. A
// pane's caption (a band along its bottom) says what the image cannot: why a frame was not
// processed, or that OpenCV's HoughCircles keeps no accumulator.
#include "widgets/ImageView.h"
#include "widgets/PipelineRunner.h"

#include <QWidget>

#include <array>

class QGridLayout;
class QLabel;

namespace omnitune {

class PipelineView : public QWidget {
    Q_OBJECT
public:
    static constexpr int kPaneCount = 5;
    enum Pane { Acquired, Segmented, Grayscale, Edges, Hough };

    explicit PipelineView(QWidget* parent = nullptr);

    void showRun(const PipelineRun& run, std::shared_ptr<const OverlayData> overlay);
    // A run the pipeline could not process (`why`): its frame, when it was read, in the
    // acquired pane with the reason on it; the other panes empty.
    void showUnprocessed(const PipelineRun& run, const QString& why);
    // Every pane empty, no overlays, no truth; `message` on the acquired pane.
    void clear(const QString& message);
    QString caption(int index) const;
    ImageView* pane(int index) const { return panes_[std::size_t(index)]; }
    ViewTransform* transform() { return &transform_; }
    OverlayOptions& overlays() { return overlays_; }
    void toggleEnlarged(int index);
    // A widget for the grid's sixth cell, beside the two lower panes (the candidate table).
    void setSideWidget(QWidget* widget);
    int enlarged() const { return enlarged_; }
    // Ground truth on every pane, and marking mode (left button marks instead of panning).
    void setTruth(const TruthOverlay& truth);
    const TruthOverlay& truth() const { return truth_; }
    void setMarking(bool on);
    // Geometry editing: the left button drags the centre and the radii (GeometryEditor)
    // instead of marking or panning; turning it on turns marking off and the other way round.
    void setEditingGeometry(bool on);
    // Any other editor of the panes (MaskEditor, RadialSensorEditor): while `editor` is set,
    // the left button reports to it through editorPressed/Dragged/Released, and each editor
    // acts only while paneEditor() is itself. Null gives the button back (panning).
    void setPaneEditor(const QObject* editor);
    const QObject* paneEditor() const { return paneEditor_; }
    double paneScale() const { return panes_[0]->scale(); }  // widget px per image px
    // Colour sampling (ColourSampler): the left button on any pane samples colours, reported
    // with its modifiers, before marking, geometry editing or panning see it.
    void setSampling(bool on);
    bool isSampling() const { return sampling_; }

signals:
    void hovered(QPointF imagePos);
    void left();
    void markPressed(QPointF imagePos);
    void markDragged(QPointF imagePos);
    void markReleased(QPointF imagePos);
    void geometryPressed(QPointF imagePos);
    void geometryDragged(QPointF imagePos);
    void geometryReleased(QPointF imagePos);
    void editorPressed(QPointF imagePos);
    void editorDragged(QPointF imagePos);
    void editorReleased(QPointF imagePos);
    void samplePressed(QPointF imagePos, Qt::KeyboardModifiers modifiers);
    void sampleDragged(QPointF imagePos);
    void sampleReleased(QPointF imagePos);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void relayout();
    void setCaption(int index, const QString& text);
    void placeCaption(int index);

    ViewTransform transform_;
    OverlayOptions overlays_;
    std::array<ImageView*, kPaneCount> panes_{};
    std::array<QLabel*, kPaneCount> captions_{};
    TruthOverlay truth_;
    QGridLayout* grid_;
    QWidget* side_ = nullptr;
    int enlarged_ = -1;
    bool editingGeometry_ = false;
    const QObject* paneEditor_ = nullptr;
    bool sampling_ = false;
};

}  // namespace omnitune
