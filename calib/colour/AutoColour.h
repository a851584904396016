#pragma once
// Automatic first colour calibration (issue 10): from one or a few frames, the dominant hue
// inside the used area is the carpet; the first field class gets one H/S box from the carpet's
// spread (percentiles), the first black and line classes black and white relative to the
// carpet's brightness, and the V floor of the ball and marker classes lowered to just above that
// black (in a dim hall a ball is darker than the defaults' floor). A first guess the user
// refines, not a replacement for looking at the
// segmented pane. Only the first field class: one dominant hue says nothing about a second
// carpet region (a dark-green patch, a cyan-green half), so any other enabled field class keeps
// the boxes the user sampled into it, and a note names it.
#include "core/ColorLut.h"
#include "core/Geometry.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct AutoColourOptions {
    int sampleStep = 2;        // every n-th pixel in x and y of the used area
    int minSaturation = 30;    // below: no reliable hue (white, grey, black), not counted for the hue peak
    int minValue = 16;         // below: no reliable hue either
    double peakSharePct = 5.0; // the carpet's hue band: bins around the peak above this share of it
    int maxHueBand = 50;       // a hue band wider than this (OpenCV hue steps) is no carpet but many colours
    double tailPct = 1.0;      // percentile cut at each end of the carpet's H and S spread (noise, outliers)
    double minSaturationShare = 0.35;  // green's S floor at least this x the carpet's median S
    int hueMarginDeg = 5;      // green's hue box this much wider than the carpet's spread on each side
    double minCarpetPct = 20.0;// the carpet must cover this share of the used pixels, else no result
    // Black up to this x the carpet's median V (the same ratio the relative black uses per frame).
    double blackVRatio = 0.45;
};

struct AutoColourResult {
    ColorLutOptions colors;     // the start options with the field, line and black classes (and overlapping ones) set
    int carpetHue = 0;          // hue of the peak, 0..179
    int carpetV = 0;            // median V of the carpet's pixels
    int carpetS = 0;            // median S
    double carpetPct = 0.0;     // share of the sampled used pixels that are carpet
    std::vector<std::string> notes;  // what else changed (a class trimmed off the carpet's hues)
    std::optional<std::string> error;  // why no calibration was made (then `colors` is the start)

    bool ok() const { return !error.has_value(); }
};

// `frames`: BGR (CV_8UC3) or UYVY (CV_8UC2) frames of the geometry's size.
AutoColourResult autoColour(const std::vector<cv::Mat>& frames, const Geometry& geometry, const ColorLutOptions& start,
                            const AutoColourOptions& options = {});

}  // namespace omnitune
