#include "widgets/MarkedSlider.h"

#include <QHelpEvent>
#include <QPainter>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QToolTip>

#include <algorithm>

namespace omnitune {

namespace {

constexpr quint8 bit(FrameMarkKind kind) { return quint8(1u << int(kind)); }

// Faint enough to read as "old", still the kind's hue so the pattern stays recognisable.
constexpr int kOutdatedAlpha = 70;

}  // namespace

MarkedSlider::MarkedSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent) {}

void MarkedSlider::clearMarks()
{
    present_.clear();
    outdated_.clear();
    update();
}

void MarkedSlider::setMarks(const QVector<FrameMark>& marks, const QVector<FrameMarkKind>& kinds)
{
    quint8 replaced = 0;
    for (FrameMarkKind k : kinds) replaced |= bit(k);
    for (int i = 0; i < present_.size(); ++i) {
        present_[i] &= quint8(~replaced);
        outdated_[i] &= quint8(~replaced);
    }
    for (const FrameMark& m : marks)
        if (replaced & bit(m.kind)) setMark(m.frame, m.kind, true);
    update();
}

void MarkedSlider::setMark(int frame, FrameMarkKind kind, bool on)
{
    if (frame < 0) return;
    if (frame >= present_.size()) {
        if (!on) return;
        present_.resize(frame + 1);
        outdated_.resize(frame + 1);
    }
    const quint8 before = present_[frame] | outdated_[frame];
    if (on)
        present_[frame] |= bit(kind);
    else
        present_[frame] &= quint8(~bit(kind));
    outdated_[frame] &= quint8(~bit(kind));
    if ((present_[frame] | outdated_[frame]) != before || on) update();
}

void MarkedSlider::setOutdated(const QVector<FrameMarkKind>& kinds)
{
    quint8 flagged = 0;
    for (FrameMarkKind k : kinds) flagged |= bit(k);
    for (int i = 0; i < present_.size(); ++i) outdated_[i] |= present_[i] & flagged;
    update();
}

bool MarkedSlider::hasMark(int frame, FrameMarkKind kind) const
{
    return frame >= 0 && frame < present_.size() && (present_[frame] & bit(kind));
}

bool MarkedSlider::isOutdated(int frame, FrameMarkKind kind) const
{
    return frame >= 0 && frame < outdated_.size() && (outdated_[frame] & bit(kind));
}

QVector<FrameMark> MarkedSlider::marks(FrameMarkKind kind) const
{
    QVector<FrameMark> out;
    for (int i = 0; i < present_.size(); ++i)
        if (present_[i] & bit(kind)) out.push_back({i, kind});
    return out;
}

bool MarkedSlider::hasOutdatedMarks() const
{
    for (quint8 b : outdated_)
        if (b) return true;
    return false;
}

QStyleOptionSlider MarkedSlider::styleOption() const
{
    QStyleOptionSlider opt;
    initStyleOption(&opt);
    return opt;
}

int MarkedSlider::handleLength() const
{
    const QStyleOptionSlider opt = styleOption();
    return style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, this).width();
}

// The style places the handle's left edge at sliderPositionFromValue(.., width - handle);
// a frame's tick sits under the handle's centre at that frame.
int MarkedSlider::tickX(int frame) const { return tickX(frame, handleLength()); }

int MarkedSlider::tickX(int frame, int handle) const
{
    return handle / 2 + QStyle::sliderPositionFromValue(minimum(), maximum(), frame, width() - handle);
}

int MarkedSlider::frameAt(int x) const
{
    const int len = handleLength();
    return QStyle::sliderValueFromPosition(minimum(), maximum(), x - len / 2, width() - len);
}

// The style centres a thin groove in the slider's height: enough height leaves room for the
// lanes on both sides of it.
QSize MarkedSlider::sizeHint() const
{
    const QSize base = QSlider::sizeHint();
    return {base.width(), std::max(base.height(), kGrooveAllowance + 2 * (std::max(kChangeLane, kBelowLanes) + 2))};
}

QSize MarkedSlider::minimumSizeHint() const
{
    const QSize base = QSlider::minimumSizeHint();
    return {base.width(), std::max(base.height(), sizeHint().height())};
}

void MarkedSlider::paintLane(QPainter& painter, FrameMarkKind kind, int top, int height) const
{
    const int handle = handleLength();
    const int frames = maximum() - minimum() + 1;
    // Half the spacing of two frames, but at least 2 px so that one changed frame among
    // thousands still shows, and at most 4 px so that neighbours in a short session stay apart.
    const int tick = std::clamp((width() - handle) / std::max(frames, 1) / 2, 2, 4);
    const QColor current = frameMarkColor(kind);
    QColor faint = current;
    faint.setAlpha(kOutdatedAlpha);
    const int last = std::min<int>(present_.size() - 1, maximum());
    for (int f = std::max(minimum(), 0); f <= last; ++f) {
        if (!(present_[f] & bit(kind))) continue;
        const bool old = outdated_[f] & bit(kind);
        painter.fillRect(tickX(f, handle) - tick / 2, top, tick, height, old ? faint : current);
    }
}

void MarkedSlider::paintEvent(QPaintEvent* event)
{
    {
        QPainter painter(this);
        const QStyleOptionSlider opt = styleOption();
        const QRect groove = style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderGroove, this);
        // Hugging the groove so they read as part of the slider; the handle covers the marks
        // of the frame on screen, which the line above the navigator describes anyway.
        const int changeTop = std::max(0, groove.top() - 1 - kChangeLane);
        const int belowTop = std::min(height() - kBelowLanes, groove.bottom() + 2);
        // Later kinds paint over earlier ones in a shared lane: a vanished ball wins.
        for (FrameMarkKind k : {FrameMarkKind::Appeared, FrameMarkKind::Moved, FrameMarkKind::Vanished})
            paintLane(painter, k, changeTop, kChangeLane);
        paintLane(painter, FrameMarkKind::Detected, belowTop, 4);
        paintLane(painter, FrameMarkKind::Truth, belowTop + 4, 2);
    }
    QSlider::paintEvent(event);
}

QString MarkedSlider::toolTipAt(int x) const
{
    const int frame = frameAt(x);
    QStringList here;
    QStringList legend;
    bool anyOutdated = false;
    for (FrameMarkKind k : kFrameMarkKinds) {
        const QString swatch = QStringLiteral("<span style='color:%1'>&#9646;</span> ").arg(frameMarkColor(k).name());
        legend << swatch + frameMarkName(k).toHtmlEscaped();
        if (!hasMark(frame, k)) continue;
        const bool old = isOutdated(frame, k);
        anyOutdated = anyOutdated || old;
        here << swatch + frameMarkName(k).toHtmlEscaped() + (old ? tr(" <i>(outdated)</i>") : QString());
    }
    QString text = tr("<b>Frame %1</b>").arg(frame);
    if (!here.isEmpty()) text += QStringLiteral("<br>") + here.join(QStringLiteral("<br>"));
    text += tr("<hr>Above the slider: changes against the saved config; below: detections and ground truth.<br>")
            + legend.join(QStringLiteral("<br>"));
    if (anyOutdated || hasOutdatedMarks())
        text += tr("<br><i>Faint marks are outdated: the config changed after Session &gt; Apply to whole session "
                   "(Ctrl+R runs it again).</i>");
    return text;
}

bool MarkedSlider::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        QToolTip::showText(help->globalPos(), toolTipAt(help->pos().x()), this);
        return true;
    }
    return QSlider::event(event);
}

}  // namespace omnitune
