#pragma once
// A mark on the frame slider: a frame and what happened there. The navigator paints them,
// the legend and the tooltip name them; kinds come from different owners (the session sweep,
// the live pipeline, the ground-truth editor), which set and clear only their own kinds.
#include <QColor>
#include <QString>
#include <QVector>

#include <array>

namespace omnitune {

enum class FrameMarkKind {
    Detected,  // the current config finds a ball here
    Appeared,  // found by the current config, not by the saved one
    Vanished,  // found by the saved config, not by the current one
    Moved,     // both find one, in different places
    Truth,     // the ball's position is marked by hand (ground truth)
};

inline constexpr std::array<FrameMarkKind, 5> kFrameMarkKinds = {FrameMarkKind::Detected, FrameMarkKind::Appeared,
                                                                 FrameMarkKind::Vanished, FrameMarkKind::Moved,
                                                                 FrameMarkKind::Truth};

struct FrameMark {
    int frame = 0;
    FrameMarkKind kind = FrameMarkKind::Detected;
};

inline bool operator==(const FrameMark& a, const FrameMark& b) { return a.frame == b.frame && a.kind == b.kind; }

// One colour and one name per kind, shared by the slider and its legend. Chosen to stay
// apart for red-green colour blindness as far as five colours can: blue / orange dominate.
inline QColor frameMarkColor(FrameMarkKind kind)
{
    switch (kind) {
    case FrameMarkKind::Detected: return QColor(0, 158, 115);    // bluish green
    case FrameMarkKind::Appeared: return QColor(0, 114, 178);    // blue
    case FrameMarkKind::Vanished: return QColor(213, 94, 0);     // vermilion
    case FrameMarkKind::Moved: return QColor(230, 159, 0);       // orange
    case FrameMarkKind::Truth: return QColor(204, 121, 167);     // reddish purple
    }
    return Qt::black;
}

inline QString frameMarkName(FrameMarkKind kind)
{
    switch (kind) {
    case FrameMarkKind::Detected: return QStringLiteral("ball detected");
    case FrameMarkKind::Appeared: return QStringLiteral("appeared (new with the current config)");
    case FrameMarkKind::Vanished: return QStringLiteral("vanished (found by the saved config only)");
    case FrameMarkKind::Moved: return QStringLiteral("moved (found elsewhere than the saved config)");
    case FrameMarkKind::Truth: return QStringLiteral("ground truth marked");
    }
    return {};
}

}  // namespace omnitune
