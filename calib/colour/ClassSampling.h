#pragma once
// What sampling does to a colour class (its list of HSV boxes): adding samples grows one box,
// removing them cuts every box that holds some (BoxFit.h). A class never loses its last box
// here (a class without a box is refused by the config); removing everything a class holds
// leaves its last box as it was and says so.
#include "calib/colour/BoxFit.h"

#include <vector>

namespace omnitune {

struct SampleEdit {
    bool changed = false;     // the boxes differ from before
    int box = -1;             // add: the box that grew (or was made)
    int boxesDropped = 0;     // remove: boxes that had nothing left and went
    bool lastBoxKept = false; // remove: the class's last box would have gone; it was kept as it was
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
