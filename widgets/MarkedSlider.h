#pragma once
// The frame slider with marks: thin coloured ticks beside the groove at the frames where
// something happened (FrameMark.h). Changes against the saved config sit above the groove,
// detections and ground truth below, so a run of thousands of frames still reads at a glance
// on a 1366 px screen. Marks from an earlier config can be flagged outdated: they are drawn
// faint and the tooltip says why, so stale results never pass for current ones.
#include "widgets/FrameMark.h"

#include <QSlider>

class QStyleOptionSlider;

namespace omnitune {

class MarkedSlider : public QSlider {
    Q_OBJECT
public:
    explicit MarkedSlider(QWidget* parent = nullptr);

    void clearMarks();
    // Replaces every mark of the kinds in `kinds` with the marks of those kinds in `marks`;
    // marks of other kinds stay (each owner replaces only its own).
    void setMarks(const QVector<FrameMark>& marks, const QVector<FrameMarkKind>& kinds);
    // Sets or clears one mark; a mark set this way is current (not outdated).
    void setMark(int frame, FrameMarkKind kind, bool on);
    // Flags every present mark of these kinds as outdated until it is set again.
    void setOutdated(const QVector<FrameMarkKind>& kinds);

    bool hasMark(int frame, FrameMarkKind kind) const;
    bool isOutdated(int frame, FrameMarkKind kind) const;
    QVector<FrameMark> marks(FrameMarkKind kind) const;  // in frame order
    bool hasOutdatedMarks() const;

    // The frame under widget x (for the tooltip and tests), and the x of a frame's tick.
    int frameAt(int x) const;
    int tickX(int frame) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;

private:
    static constexpr int kChangeLane = 5;  // px above the groove: appeared / vanished / moved
    static constexpr int kBelowLanes = 6;  // px below: detected (4), truth (2)
    static constexpr int kGrooveAllowance = 8;  // px: the groove of common styles (Fusion: 7)

    QStyleOptionSlider styleOption() const;
    int handleLength() const;
    int tickX(int frame, int handle) const;
    QString toolTipAt(int x) const;
    void paintLane(QPainter& painter, FrameMarkKind kind, int top, int height) const;

    // Bit (1 << kind) per frame, indexed by frame; grown on demand.
    QVector<quint8> present_;
    QVector<quint8> outdated_;
};

}  // namespace omnitune
