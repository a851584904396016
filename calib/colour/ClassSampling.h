#pragma once
// What sampling does to a colour class (its list of HSV boxes): adding samples grows one box,
// removing them cuts every box that holds some (BoxFit.h). A class never loses its last box
// here (a class without a box is refused by the config): when removing leaves nothing of it,
// it stays as a box that is off (matches nothing), which the next added samples replace.
#include "calib/colour/BoxFit.h"

#include <vector>

namespace omnitune {

struct SampleEdit {
    bool changed = false;     // the boxes differ from before
    int box = -1;             // add: the box that grew (or was made)
    int boxesDropped = 0;     // remove: boxes that had nothing left and went
    bool lastBoxOff = false;  // remove: nothing was left of the class's boxes; one stays, off
    int samplesOut = 0;       // remove: samples that the class held before and does not now
};

// Grows boxes[box] to cover the samples; appends a box of them when `box` is out of range (a
// class without boxes, or "new box").
SampleEdit addSamples(std::vector<HsvRange>& boxes, int box, const std::vector<Hsv>& samples,
                      const BoxFitOptions& options = {});

// Cuts every box holding samples so that they fall outside it.
SampleEdit removeSamples(std::vector<HsvRange>& boxes, const std::vector<Hsv>& samples,
                         const BoxFitOptions& options = {});

}  // namespace omnitune
