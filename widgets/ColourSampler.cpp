#include "widgets/ColourSampler.h"

#include "calib/colour/ClassSampling.h"
#include "calib/colour/ColourSamples.h"
#include "calib/colour/HsvImage.h"
#include "calib/colour/SampleArea.h"
#include "core/ColourClasses.h"
#include "core/Geometry.h"
#include "widgets/ConfigDocument.h"
#include "widgets/PaneEditMode.h"
#include "widgets/PipelineView.h"

#include <QAction>
#include <QMenu>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

cv::Point toPixel(QPointF p) { return {int(std::floor(p.x())), int(std::floor(p.y()))}; }

QString boxText(const HsvRange& b)
{
    return QObject::tr("H %1..%2, S %3..%4, V %5..%6").arg(b.hMin).arg(b.hMax).arg(b.sMin).arg(b.sMax).arg(b.vMin).arg(b.vMax);
}

}  // namespace

ColourSampler::ColourSampler(ConfigDocument* doc, PipelineView* view, QObject* parent)
    : QObject(parent), doc_(doc), view_(view)
{
    connect(view_, &PipelineView::samplePressed, this, &ColourSampler::press);
    connect(view_, &PipelineView::sampleDragged, this, &ColourSampler::drag);
    connect(view_, &PipelineView::sampleReleased, this, &ColourSampler::release);
}

void ColourSampler::setSampling(bool on)
{
    if (on == sampling_) return;
    setMode(on);
}

void ColourSampler::setMode(bool on)
{
    sampling_ = on;
    active_ = false;
    view_->setSampling(on);
    if (samplingAction_) samplingAction_->setChecked(on);
    for (QAction* a : sizeActions_) a->setEnabled(on);
    emit samplingChanged(on);  // marking and geometry editing give the left button up
    emit message(on ? tr("Sampling colours into the selected class: drag adds (Ctrl: removes), Shift+drag a rectangle, "
                         "W the magic wand, [ ] the brush size; C ends")
                    : tr("Colour sampling off"));
}

void ColourSampler::setTarget(int classIndex, int box)
{
    class_ = classIndex;
    box_ = box;
}

void ColourSampler::setRun(std::shared_ptr<const PipelineRun> run) { run_ = std::move(run); }

BoxFitOptions ColourSampler::fitOptions() const
{
    BoxFitOptions o;
    o.outlierPct = doc_->config().colors.sampleOutlierPct;
    return o;
}

void ColourSampler::setTool(Tool tool)
{
    if (tool == tool_) return;
    tool_ = tool;
    if (wandAction_) wandAction_->setChecked(tool == Tool::Wand);
    emit toolChanged(tool);
    emit message(tool == Tool::Wand ? tr("Magic wand: a click takes the region of similar colour around it")
                                    : tr("Brush: %1 px radius").arg(radius_));
}

void ColourSampler::setBrushRadius(int px)
{
    px = std::clamp(px, 0, kMaxBrushRadius);
    if (px == radius_) return;
    radius_ = px;
    emit brushRadiusChanged(px);
}

void ColourSampler::fillMenu(QMenu* menu)
{
    samplingAction_ = addEditModeAction(menu, this, &ColourSampler::setSampling, tr("&Sample colours on the panes"),
                                        QStringLiteral("sampleColours"), QKeySequence(Qt::Key_C),
                                        tr("Left button on any pane adds colours to the selected class; Ctrl removes, "
                                           "Shift drags a rectangle"));
    wandAction_ = menu->addAction(tr("Magic &wand instead of the brush"));
    wandAction_->setObjectName("magicWand");
    wandAction_->setCheckable(true);
    wandAction_->setShortcut(QKeySequence(Qt::Key_W));
    connect(wandAction_, &QAction::toggled, this, [this](bool on) { setTool(on ? Tool::Wand : Tool::Brush); });
    // Only while sampling: the mask editor has its own [ and ] (an ambiguous shortcut fires neither).
    QAction* smaller = menu->addAction(tr("Smaller brush"));
    smaller->setShortcut(QKeySequence(Qt::Key_BracketLeft));
    connect(smaller, &QAction::triggered, this, [this] { setBrushRadius(radius_ - 1); });
    QAction* larger = menu->addAction(tr("Larger brush"));
    larger->setShortcut(QKeySequence(Qt::Key_BracketRight));
    connect(larger, &QAction::triggered, this, [this] { setBrushRadius(radius_ + 1); });
    sizeActions_ = {smaller, larger};
    for (QAction* a : sizeActions_) a->setEnabled(sampling_);
}

void ColourSampler::press(QPointF p, Qt::KeyboardModifiers modifiers)
{
    active_ = false;
    const auto& classes = doc_->config().colors.classes;
    if (class_ < 0 || class_ >= int(classes.size())) {
        emit message(tr("Choose the class to sample into in the Colours panel first"));
        return;
    }
    const std::shared_ptr<const PipelineRun> run = run_;
    const cv::Size size(run ? run->config.geometry.imageWidth : 0, run ? run->config.geometry.imageHeight : 0);
    if (!run || run->frame.empty() || !run->error.isEmpty() || run->frame.size() != size) {
        emit message(tr("The frame on screen was not processed: no colours to sample from it"));
        return;
    }
    strokeRun_ = run;
    strokeUsed_ = Geometry(run->config.geometry, run->config.mask).usedMask();
    remove_ = modifiers.testFlag(Qt::ControlModifier);
    rect_ = modifiers.testFlag(Qt::ShiftModifier);
    wandClick_ = !rect_ && tool_ == Tool::Wand;
    if (wandClick_) strokeHsv_ = hsvImage(run->frame, run->format);
    start_ = doc_->config();
    path_ = {toPixel(p)};
    active_ = true;
    drag(p);
}

void ColourSampler::drag(QPointF p)
{
    if (!active_) return;
    const cv::Point q = toPixel(p);
    if (rect_ && path_.size() > 1) path_.back() = q;  // a rectangle needs its two corners only
    else if (!wandClick_ && q != path_.back()) path_.push_back(q);
    const StrokeEdit e = edited();
    // Live on the panes, without an undo step per mouse move (the release makes one).
    if (e.changed && checkConfig(e.config).empty()) doc_->applyConfig(e.config);
}

void ColourSampler::release(QPointF p)
{
    if (!active_) return;
    drag(p);
    active_ = false;
    const StrokeEdit e = edited();
    doc_->applyConfig(start_);  // the undo step goes from where the stroke began
    if (e.changed) {
        if (const auto why = doc_->replaceConfig(e.config, e.undoText)) {
            emit message(tr("Not changed: %1").arg(*why));
            return;
        }
        emit targetEdited(class_, e.box);
    }
    emit message(e.summary);
}

ColourSampler::StrokeEdit ColourSampler::edited() const
{
    StrokeEdit res;
    res.config = start_;
    ColourClasses& classes = res.config.colors.classes;
    if (class_ < 0 || class_ >= int(classes.size()) || !strokeRun_) return res;
    ColourClassDef& c = classes[std::size_t(class_)];
    const cv::Size size = strokeRun_->frame.size();
    const std::vector<cv::Point> pixels = rect_        ? rectPixels(path_.front(), path_.back(), size)
                                          : wandClick_ ? magicWand(strokeHsv_, strokeUsed_, path_.front(), wand_)
                                                       : strokePixels(path_, radius_, size);
    const ColourSamples samples = sampleColours(strokeRun_->frame, strokeRun_->format, strokeUsed_, pixels);
    const QString name = QString::fromStdString(c.name);
    const QString ignored = samples.masked > 0 ? tr(" (%n masked pixel(s) ignored: not processed)", "", samples.masked)
                                               : QString();
    if (samples.hsv.empty()) {
        res.summary = pixels.empty() ? tr("No pixel sampled (outside the processed area)")
                                     : tr("Nothing sampled: all %n pixel(s) are masked (not processed)", "", samples.masked);
        return res;
    }
    const int n = int(samples.hsv.size());
    if (remove_) {
        const SampleEdit e = removeSamples(c.boxes, samples.hsv, fitOptions());
        res.changed = e.changed;
        res.undoText = tr("Remove colours from %1").arg(name);
        res.summary = tr("%1: %n pixel(s) sampled", "", n).arg(name) + ignored +
                      tr(", %n taken out of the class", "", e.samplesOut);
        if (e.boxesDropped > 0) res.summary += tr(", %n box(es) with nothing left removed", "", e.boxesDropped);
        if (e.lastBoxOff) res.summary += tr("; nothing is left of the class: its box is off until you add colours");
        return res;
    }
    const SampleEdit e = addSamples(c.boxes, box_, samples.hsv, fitOptions());
    res.changed = e.changed;
    res.box = e.box;
    res.undoText = tr("Add colours to %1").arg(name);
    res.summary = tr("%1: %n pixel(s) added", "", n).arg(name) + ignored;
    if (e.box >= 0) res.summary += tr("; box %1 now %2").arg(e.box + 1).arg(boxText(c.boxes[std::size_t(e.box)]));
    if (e.changed && !c.enabled) {
        c.enabled = true;  // sampling into a class that is off means the user wants it on
        res.summary += tr(" (%1 was off: now on)").arg(name);
    }
    if (!e.changed) res.summary += tr(" (already in the class)");
    return res;
}

}  // namespace omnitune
