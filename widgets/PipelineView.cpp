#include "widgets/PipelineView.h"

#include <QGridLayout>

namespace omnitune {

PipelineView::PipelineView(QWidget* parent) : QWidget(parent), grid_(new QGridLayout(this))
{
    const char* titles[kPaneCount] = {QT_TR_NOOP("1 acquired"), QT_TR_NOOP("2 segmented"),
                                      QT_TR_NOOP("3 grayscale (green/non-green)"), QT_TR_NOOP("4 edges (Canny)"),
                                      QT_TR_NOOP("5 Hough accumulator")};
    grid_->setContentsMargins(0, 0, 0, 0);
    grid_->setSpacing(2);
    for (int i = 0; i < kPaneCount; ++i) {
        auto* view = new ImageView(tr(titles[i]), &transform_, &overlays_, this);
        panes_[std::size_t(i)] = view;
        connect(view, &ImageView::hovered, this, &PipelineView::hovered);
        connect(view, &ImageView::left, this, &PipelineView::left);
        connect(view, &ImageView::doubleClicked, this, [this, i] { toggleEnlarged(i); });
        connect(view, &ImageView::markPressed, this, &PipelineView::markPressed);
        connect(view, &ImageView::markDragged, this, &PipelineView::markDragged);
        connect(view, &ImageView::markReleased, this, &PipelineView::markReleased);
    }
    relayout();
}

void PipelineView::relayout()
{
    for (ImageView* v : panes_) grid_->removeWidget(v);
    if (side_) grid_->removeWidget(side_);
    if (enlarged_ >= 0) {
        for (int i = 0; i < kPaneCount; ++i) panes_[std::size_t(i)]->setVisible(i == enlarged_);
        if (side_) side_->hide();
        grid_->addWidget(panes_[std::size_t(enlarged_)], 0, 0);
        return;
    }
    if (side_) {
        side_->show();
        grid_->addWidget(side_, 1, 2);
    }
    // Three on top, two below: fits a 1366x768 laptop beside the tuning panel at 4:3.
    for (int i = 0; i < kPaneCount; ++i) {
        panes_[std::size_t(i)]->setVisible(true);
        grid_->addWidget(panes_[std::size_t(i)], i / 3, i % 3);
    }
}

void PipelineView::setSideWidget(QWidget* widget)
{
    side_ = widget;
    side_->setParent(this);
    relayout();
}

void PipelineView::toggleEnlarged(int index)
{
    enlarged_ = enlarged_ == index ? -1 : index;
    relayout();
}

void PipelineView::setTruth(const TruthOverlay& truth)
{
    for (ImageView* v : panes_) v->setTruth(truth);
}

void PipelineView::setMarking(bool on)
{
    for (ImageView* v : panes_) v->setMarking(on);
}

void PipelineView::showRun(const PipelineRun& run, std::shared_ptr<const OverlayData> overlay)
{
    const StageImages& s = run.result.stages;
    const cv::Mat* images[kPaneCount] = {&s.acquired, &s.segmented, &s.grayscale, &s.edges, &s.hough};
    for (int i = 0; i < kPaneCount; ++i) {
        panes_[std::size_t(i)]->setImage(toQImage(*images[i]));
        panes_[std::size_t(i)]->setOverlay(overlay);
    }
}

}  // namespace omnitune
