#include "calib/eval/SessionComparison.h"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace omnitune {

namespace {

bool foundBall(const FrameOutcome& o) { return o.processed && o.detection.found; }

FrameComparison compareFrame(const FrameOutcome& current, const FrameOutcome& saved, double movedPx)
{
    FrameComparison c;
    c.frame = current.frame;
    const bool now = foundBall(current);
    const bool before = foundBall(saved);
    if (now && before) {
        c.shiftPx = std::hypot(current.detection.px - saved.detection.px, current.detection.py - saved.detection.py);
        c.change = c.shiftPx > movedPx ? FrameChange::Moved : FrameChange::Same;
    } else if (now) {
        c.change = FrameChange::Appeared;
    } else if (before) {
        c.change = FrameChange::Vanished;
    }
    return c;
}

}  // namespace

const char* frameChangeName(FrameChange change)
{
    switch (change) {
    case FrameChange::Same: return "same";
    case FrameChange::Appeared: return "appeared";
    case FrameChange::Vanished: return "vanished";
    case FrameChange::Moved: return "moved";
    }
    return "?";
}

SessionComparison compareSessions(const std::vector<FrameOutcome>& current, const std::vector<FrameOutcome>& saved,
                                  const ComparisonOptions& options)
{
    if (!(options.movedPx > 0)) throw std::invalid_argument("ComparisonOptions::movedPx must be > 0");
    std::unordered_map<int, const FrameOutcome*> savedByFrame;
    savedByFrame.reserve(saved.size());
    for (const FrameOutcome& o : saved) savedByFrame.emplace(o.frame, &o);

    SessionComparison result;
    result.frames.reserve(current.size());
    for (const FrameOutcome& o : current) {
        const auto s = savedByFrame.find(o.frame);
        if (s == savedByFrame.end()) continue;
        const FrameComparison c = compareFrame(o, *s->second, options.movedPx);
        switch (c.change) {
        case FrameChange::Same: ++result.same; break;
        case FrameChange::Appeared: ++result.appeared; break;
        case FrameChange::Vanished: ++result.vanished; break;
        case FrameChange::Moved: ++result.moved; break;
        }
        result.frames.push_back(c);
    }
    return result;
}

}  // namespace omnitune
