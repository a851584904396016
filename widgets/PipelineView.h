#pragma once
// The five stage panes of thesis Fig. 4.6 plus the Hough accumulator, side by side under one
// zoom/pan. Double-clicking a pane enlarges it; double-clicking again brings the others back.
#include "widgets/ImageView.h"
#include "widgets/PipelineRunner.h"

#include <QWidget>

#include <array>

class QGridLayout;

namespace omnitune {

class PipelineView : public QWidget {
    Q_OBJECT
public:
    static constexpr int kPaneCount = 5;
    enum Pane { Acquired, Segmented, Grayscale, Edges, Hough };

    explicit PipelineView(QWidget* parent = nullptr);

    void showRun(const PipelineRun& run, std::shared_ptr<const OverlayData> overlay);
    ImageView* pane(int index) const { return panes_[std::size_t(index)]; }
    ViewTransform* transform() { return &transform_; }
    OverlayOptions& overlays() { return overlays_; }
    void toggleEnlarged(int index);
    // A widget for the grid's sixth cell, beside the two lower panes (the candidate table).
    void setSideWidget(QWidget* widget);
    int enlarged() const { return enlarged_; }
    // Ground truth on every pane, and marking mode (left button marks instead of panning).
    void setTruth(const TruthOverlay& truth);
    void setMarking(bool on);

signals:
    void hovered(QPointF imagePos);
    void left();
    void markPressed(QPointF imagePos);
    void markDragged(QPointF imagePos);
    void markReleased(QPointF imagePos);

private:
    void relayout();

    ViewTransform transform_;
    OverlayOptions overlays_;
    std::array<ImageView*, kPaneCount> panes_{};
    QGridLayout* grid_;
    QWidget* side_ = nullptr;
    int enlarged_ = -1;
};

}  // namespace omnitune
