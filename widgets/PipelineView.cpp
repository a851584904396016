#include "widgets/PipelineView.h"

#include "core/ColorLut.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QMouseEvent>

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
        // The left button is captured for truth marking, the geometry or another editor: one at a time.
        connect(view, &ImageView::markPressed, this, [this](QPointF p) {
            if (paneEditor_) emit editorPressed(p);
            else if (editingGeometry_) emit geometryPressed(p); else emit markPressed(p);
        });
        connect(view, &ImageView::markDragged, this, [this](QPointF p) {
            if (paneEditor_) emit editorDragged(p);
            else if (editingGeometry_) emit geometryDragged(p); else emit markDragged(p);
        });
        connect(view, &ImageView::markReleased, this, [this](QPointF p) {
            if (paneEditor_) emit editorReleased(p);
            else if (editingGeometry_) emit geometryReleased(p); else emit markReleased(p);
        });
        // A click on a pane takes the keyboard back from an editor: arrows, Space, T act again.
        view->setFocusPolicy(Qt::ClickFocus);
        auto* caption = new QLabel(view);
        caption->setObjectName(QStringLiteral("caption"));
        caption->setWordWrap(true);
        caption->setAlignment(Qt::AlignCenter);
        caption->setAttribute(Qt::WA_TransparentForMouseEvents);  // marks and pans go to the pane
        caption->setStyleSheet(QStringLiteral("color: white; background: rgba(0, 0, 0, 190); padding: 4px;"));
        caption->hide();
        captions_[std::size_t(i)] = caption;
        view->installEventFilter(this);
    }
    setFocusPolicy(Qt::ClickFocus);
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
    truth_ = truth;
    for (ImageView* v : panes_) v->setTruth(truth);
}

void PipelineView::setMarking(bool on)
{
    editingGeometry_ = false;
    paneEditor_ = nullptr;
    for (ImageView* v : panes_) v->setMarking(on);
}

void PipelineView::setEditingGeometry(bool on)
{
    for (ImageView* v : panes_) v->setMarking(on);
    editingGeometry_ = on;
    if (on) paneEditor_ = nullptr;
}

void PipelineView::setPaneEditor(const QObject* editor)
{
    for (ImageView* v : panes_) v->setMarking(editor != nullptr);
    paneEditor_ = editor;
    if (editor) editingGeometry_ = false;
}

void PipelineView::showRun(const PipelineRun& run, std::shared_ptr<const OverlayData> overlay)
{
    const StageImages& s = run.result.stages;
    const cv::Mat* images[kPaneCount] = {&s.acquired, &s.segmented, &s.grayscale, &s.edges, &s.hough};
    for (int i = 0; i < kPaneCount; ++i) {
        panes_[std::size_t(i)]->setImage(toQImage(*images[i]));
        panes_[std::size_t(i)]->setOverlay(overlay);
        setCaption(i, QString());
    }
    // cv::HoughCircles votes internally and returns only circles: there is no accumulator to
    // show. The pane shows the edges instead, under the circles it returned (the overlay).
    if (run.config.algorithm == Algorithm::OpenCv) {
        panes_[Hough]->setImage(toQImage(s.edges));
        setCaption(Hough, tr("algorithm: opencv. OpenCV's HoughCircles keeps no accumulator: its circles (\"cv\") "
                             "are drawn over the edges"));
    } else if (run.config.algorithm == Algorithm::Combined) {
        for (const BallCandidate& c : run.result.candidates)
            if (c.source == CandidateSource::OpenCvHough) {
                setCaption(Hough, tr("specific votes; the \"cv\" circles come from OpenCV's HoughCircles, "
                                     "which keeps no accumulator"));
                break;
            }
    }
}

void PipelineView::showUnprocessed(const PipelineRun& run, const QString& why)
{
    cv::Mat shown = run.frame;
    if (run.format == PixelFormat::Uyvy && !shown.empty() && shown.type() == CV_8UC2 && shown.cols % 2 == 0)
        convertUyvyToBgr(run.frame, shown);
    for (int i = 0; i < kPaneCount; ++i) {
        panes_[std::size_t(i)]->setImage(i == Acquired ? toQImage(shown) : QImage());
        panes_[std::size_t(i)]->setOverlay(nullptr);  // the config's geometry does not fit this frame
        setCaption(i, QString());
    }
    setCaption(Acquired, why);
}

void PipelineView::clear(const QString& message)
{
    for (int i = 0; i < kPaneCount; ++i) {
        panes_[std::size_t(i)]->setImage(QImage());
        panes_[std::size_t(i)]->setOverlay(nullptr);
        setCaption(i, QString());
    }
    setTruth(TruthOverlay{});
    setCaption(Acquired, message);
}

QString PipelineView::caption(int index) const
{
    const QLabel* c = captions_[std::size_t(index)];
    return c->isHidden() ? QString() : c->text();
}

void PipelineView::setCaption(int index, const QString& text)
{
    QLabel* c = captions_[std::size_t(index)];
    c->setText(text);
    c->setVisible(!text.isEmpty());
    placeCaption(index);
}

// A band along the pane's bottom edge, as tall as its wrapped text, clear of the title.
void PipelineView::placeCaption(int index)
{
    QLabel* c = captions_[std::size_t(index)];
    if (c->isHidden()) return;
    const ImageView* pane = panes_[std::size_t(index)];
    const int w = pane->width();
    const int h = std::min(c->heightForWidth(w), pane->height() - 30);
    c->setGeometry(0, pane->height() - h, w, h);
    c->raise();
}

void PipelineView::setSampling(bool on)
{
    sampling_ = on;
    for (ImageView* v : panes_) v->setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
}

bool PipelineView::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Resize)
        for (int i = 0; i < kPaneCount; ++i)
            if (watched == panes_[std::size_t(i)]) placeCaption(i);
    // Colour sampling takes the left button with its modifiers (add, remove, rectangle) before
    // the pane pans or marks; the middle button still pans.
    const auto type = event->type();
    if (sampling_ && (type == QEvent::MouseButtonPress || type == QEvent::MouseButtonDblClick ||
                      type == QEvent::MouseMove || type == QEvent::MouseButtonRelease)) {
        auto* pane = qobject_cast<ImageView*>(watched);
        auto* mouse = static_cast<QMouseEvent*>(event);
        const bool left = mouse->button() == Qt::LeftButton || (type == QEvent::MouseMove && (mouse->buttons() & Qt::LeftButton));
        if (pane && left && !pane->image().isNull()) {
            const QPointF p = pane->toImage(mouse->localPos());
            if (type == QEvent::MouseMove) emit sampleDragged(p);
            else if (type == QEvent::MouseButtonRelease) emit sampleReleased(p);
            else emit samplePressed(p, mouse->modifiers());
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace omnitune
