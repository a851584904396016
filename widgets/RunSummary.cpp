#include "widgets/RunSummary.h"

#include "widgets/PipelineRunner.h"

#include <QHBoxLayout>
#include <QLabel>

#include <algorithm>

namespace omnitune {

RunSummary::RunSummary(QWidget* parent)
    : QWidget(parent), result_(new QLabel(this)), truth_(new QLabel(this)), timing_(new QLabel(this))
{
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(2);  // the window's own spacing
    result_->setObjectName("result");
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row->addWidget(result_, 1);
    truth_->setObjectName("truth");
    truth_->setStyleSheet("color: #c030c0");  // the truth overlay's colour
    truth_->setWordWrap(true);  // the marking banner must never widen the window
    result_->setWordWrap(true);
    // Room for two lines from the start, so the panes do not jump while playing when a
    // result or a truth line wraps.
    for (QLabel* l : {result_, truth_})
        l->setMinimumHeight(l->fontMetrics().boundingRect(QRect(0, 0, 4000, 4000), Qt::TextWordWrap, "X\nX").height() + 2);
    row->addWidget(truth_, 1);
    timing_->setToolTip(tr("Time per stage of this frame, ms: segmentation, binary image, Canny edges, Hough, "
                           "validation; total and the running average over about 100 frames"));
}

void RunSummary::opening(const QString& sourceName)
{
    result_->setText(tr("Opening %1...").arg(sourceName));
    timing_->clear();
    averaged_ = 0;
    averageMs_ = 0;
}

void RunSummary::showUnprocessed(const PipelineRun& run, const QString& why)
{
    // Short here (one line under the panes); the whole reason is on pane 1 and in the tooltip.
    result_->setText(run.frameUnreadable ? tr("Frame %1 skipped: it cannot be read (pane 1 says why)").arg(run.frameIndex)
                                         : tr("Frame %1 not processed (pane 1 says why)").arg(run.frameIndex));
    result_->setToolTip(why);
}

void RunSummary::showResult(const PipelineRun& run)
{
    result_->setToolTip(QString());
    const BallDetection& d = run.result.detection;
    if (d.found) {
        result_->setText(tr("Frame %1: ball at x %2 m, y %3 m (%4 m away, radius %5 px)")
                             .arg(run.frameIndex).arg(d.xM, 0, 'f', 2).arg(d.yM, 0, 'f', 2)
                             .arg(d.distanceM, 0, 'f', 2).arg(d.radiusPx, 0, 'f', 1));
    } else {
        result_->setText(tr("Frame %1: no ball. %2 candidate(s); see the table for the test each failed")
                             .arg(run.frameIndex).arg(run.result.candidates.size()));
    }
    const StageTimings& t = run.result.timings;
    averageMs_ = (averageMs_ * averaged_ + t.totalMs) / (averaged_ + 1);
    averaged_ = std::min(averaged_ + 1, 99);  // a running average over about the last 100 frames
    // Short: status messages share the status bar and must not be cut off; the stages are in
    // the tooltip.
    const PipelineResult& r = run.result;
    // A blurred frame is marked: its segmentation differs from what the acquired pane shows.
    timing_->setText(tr("%1 ms (avg %2)").arg(t.totalMs, 0, 'f', 1).arg(averageMs_, 0, 'f', 1) +
                     (r.denoised ? tr(", noisy: blurred") : QString()));
    const QString noise = r.frameNoise <= 0.0 ? tr("Frame noise not measured (denoise.above_noise 0).")
                          : r.denoised ? tr("Frame noise %1 levels, above denoise.above_noise: the frame was blurred "
                                            "before segmentation.").arg(r.frameNoise, 0, 'f', 1)
                                       : tr("Frame noise %1 levels: not blurred.").arg(r.frameNoise, 0, 'f', 1);
    timing_->setToolTip(tr("This frame, ms: segmentation %1, binary image %2, Canny edges %3, Hough %4, validation %5; "
                           "total %6, and the running average over about 100 frames %7")
                            .arg(t.segmentMs, 0, 'f', 1).arg(t.binaryMs, 0, 'f', 1).arg(t.edgesMs, 0, 'f', 1)
                            .arg(t.houghMs, 0, 'f', 1).arg(t.validationMs, 0, 'f', 1).arg(t.totalMs, 0, 'f', 1)
                            .arg(averageMs_, 0, 'f', 1) +
                        "\n" + noise);
}

void RunSummary::setTruth(const QString& text, bool marking)
{
    truth_->setText(text);
    // Marking mode changes what the left button does: it must be impossible to miss.
    truth_->setStyleSheet(marking ? "color: white; background: #a020a0; padding: 2px" : "color: #c030c0");
}

}  // namespace omnitune
