#pragma once
// What a config change did to a session, frame by frame: the detections of the config being
// tuned against those of the saved one. Pure: two outcome lists in, one change per frame and
// the counts out. The GUI's "apply to whole session" marks these on the frame slider.
#include "calib/eval/Evaluation.h"

#include <vector>

namespace omnitune {

enum class FrameChange {
    Same,      // both found the ball within movedPx of each other, or neither found one
    Appeared,  // only the current config finds a ball
    Vanished,  // only the saved config finds a ball
    Moved,     // both find one, farther apart than movedPx: most likely another object
};

const char* frameChangeName(FrameChange change);

struct ComparisonOptions {
    // px between the two detections' centres above which a frame counts as Moved, > 0.
    // 5 px is about a far ball's radius (r ~ 6 px at 3 m): below it the same ball re-centred
    // by slightly different edges, above it the detector most likely locked onto something
    // else. Smaller reports edge jitter as moves; larger hides a switch to a nearby object.
    double movedPx = 5.0;
};

struct FrameComparison {
    int frame = 0;
    FrameChange change = FrameChange::Same;
    double shiftPx = 0.0;  // distance between the two centres when both found a ball, else 0
};

struct SessionComparison {
    std::vector<FrameComparison> frames;  // in the current outcomes' order
    int same = 0;
    int appeared = 0;
    int vanished = 0;
    int moved = 0;

    int changed() const { return appeared + vanished + moved; }
};

// Pairs the outcomes by frame number. A frame that could not be processed counts as "no
// ball" (a config that fails on a frame has lost its detection there). Frames found in only
// one list are left out: there is nothing to compare them with.
SessionComparison compareSessions(const std::vector<FrameOutcome>& current, const std::vector<FrameOutcome>& saved,
                                  const ComparisonOptions& options = {});

}  // namespace omnitune
