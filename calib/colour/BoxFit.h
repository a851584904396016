#pragma once
// From sampled colours to HSV boxes: the smallest box that covers the samples, growing a box to
// cover more, and cutting a box so that samples fall outside. Hue is a circle: red samples
// (hues 175..3) give the wrapped box 175..3, not 3..175.
//
// Outliers: a brush stroke over a ball also catches its blurred edge, a rectangle a few pixels
// of carpet. Each channel ignores `outlierPct` percent of the samples at each end of its
// spread (for hue: the shortest arc holding all but 2 x outlierPct percent of them), so a few
// stray pixels do not stretch the box. With fewer than 100 / outlierPct samples nothing is
// ignored (the cut rounds down), so a single click is always covered.
#include "core/FrameColour.h"
#include "core/HsvRange.h"

#include <optional>
#include <vector>

namespace omnitune {

struct BoxFitOptions {
    // Percent of the samples ignored at each end of each channel's spread, 0..25. 0: every
    // sample is covered (one stray pixel can stretch the box); larger: tighter boxes that leave
    // some of a class's real colours out. Ours, measured on nothing yet: 1 % keeps a brush
    // stroke's blurred edge pixels from stretching a ball's box.
    double outlierPct = 1.0;
    // A hue arc wider than this (hue steps, 1..180) becomes every hue: samples that spread so far
    // are achromatic (white, grey, black), where hue is noise.
    int fullHueAbove = 120;
};

// The box covering the samples (enabled); nullopt when there are none.
std::optional<HsvRange> fitBox(const std::vector<Hsv>& samples, const BoxFitOptions& options = {});

// `box` grown so it also covers the samples' box (the smallest box containing both). A disabled
// box counts as empty: the result is the samples' box.
HsvRange growBox(const HsvRange& box, const std::vector<Hsv>& samples, const BoxFitOptions& options = {});

// Removing samples from a box: the box is shrunk on one side of one channel (H from either end
// of its arc, S or V from below or above) so the samples inside it fall outside, choosing the
// side that keeps the most HSV volume. Shrinking, not splitting a box in two: it never adds
// boxes behind the user's back, and a second stroke cuts again. The samples of each channel
// that the cut may leave inside are the outliers of BoxFitOptions.
struct BoxCut {
    std::optional<HsvRange> box;  // the shrunk box; nullopt when nothing of it would be left
    bool changed = false;         // false: no sample was inside, `box` is the input
    int removedSamples = 0;       // samples that were inside the box and are outside now
};
BoxCut cutBox(const HsvRange& box, const std::vector<Hsv>& samples, const BoxFitOptions& options = {});

// Hue steps x S steps x V steps the box covers (0 when disabled).
long long boxVolume(const HsvRange& box);

}  // namespace omnitune
