#include "calib/colour/ClassSampling.h"

#include "calib/colour/ClassShares.h"

namespace omnitune {

SampleEdit addSamples(std::vector<HsvRange>& boxes, int box, const std::vector<Hsv>& samples, const BoxFitOptions& o)
{
    SampleEdit res;
    const std::optional<HsvRange> fitted = fitBox(samples, o);
    if (!fitted) return res;
    if (box < 0 || box >= int(boxes.size())) {
        boxes.push_back(*fitted);
        res.box = int(boxes.size()) - 1;
        res.changed = true;
        return res;
    }
    const HsvRange grown = growBox(boxes[std::size_t(box)], samples, o);
    res.box = box;
    res.changed = grown != boxes[std::size_t(box)];
    boxes[std::size_t(box)] = grown;
    return res;
}

SampleEdit removeSamples(std::vector<HsvRange>& boxes, const std::vector<Hsv>& samples, const BoxFitOptions& o)
{
    SampleEdit res;
    int heldBefore = 0;
    for (const Hsv& p : samples) heldBefore += boxesContain(boxes, p.h, p.s, p.v) ? 1 : 0;
    std::vector<HsvRange> kept;
    for (const HsvRange& b : boxes) {
        const BoxCut cut = cutBox(b, samples, o);
        res.changed = res.changed || cut.changed;
        if (cut.box) kept.push_back(*cut.box);
        else ++res.boxesDropped;
    }
    if (kept.empty() && !boxes.empty()) {
        // Nothing left of the class: one box stays, off, so the config still takes the class
        // and the next samples added make the box anew (growBox treats an off box as empty).
        HsvRange off = boxes.back();
        off.enabled = false;
        kept.push_back(off);
        --res.boxesDropped;
        res.lastBoxOff = true;
    }
    boxes = std::move(kept);
    int heldAfter = 0;
    for (const Hsv& p : samples) heldAfter += boxesContain(boxes, p.h, p.s, p.v) ? 1 : 0;
    res.samplesOut = heldBefore - heldAfter;
    return res;
}

}  // namespace omnitune
