#pragma once
// How the current frame's processed pixels divide among the colour classes: each class's share
// (a pixel belongs to the first class in priority order whose boxes contain it, as in the LUT),
// the share in no class, and the pixels two or more classes claim (where the priority order
// decides, and where the user may want to tighten a box).
//
// Exact HSV boxes per pixel, not the LUT, for the overlaps (which boxes claim a pixel);
// countSegmented() then takes the shares from the segmented image itself, so that they say
// what the pane shows (the LUT's quantisation, and relative black decided per frame from the
// carpet's brightness: a dim carpet inside the fixed black box is not "95 % black").
#include "core/HsvRange.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

// The boxes of each class, in priority order (index 0 first).
using ClassBoxes = std::vector<std::vector<HsvRange>>;

struct ClassShares {
    int processed = 0;        // processed pixels counted
    std::vector<int> counts;  // per class: pixels it gets
    int unclassified = 0;     // pixels no class contains
    cv::Mat overlap;          // CV_8UC1, frame size: 255 where two or more classes contain the pixel
    int overlapCount = 0;

    // Percent of the processed pixels (0 when none were processed).
    double pct(int pixels) const { return processed > 0 ? 100.0 * pixels / processed : 0.0; }
};

// `hsv`: the frame in OpenCV HSV; `used`: CV_8UC1, non-zero = processed (empty: every pixel).
ClassShares classShares(const cv::Mat& hsv, const cv::Mat& used, const ClassBoxes& classes);

// Replaces `shares`' processed, counts and unclassified with those of `classes` (CV_8UC1 class
// ids as the pipeline segmented them: 0 none, index + 1 a class) over `used`; keeps the overlap.
void countSegmented(ClassShares& shares, const cv::Mat& classes, const cv::Mat& used);

// Whether any of the boxes contains the colour.
bool boxesContain(const std::vector<HsvRange>& boxes, int h, int s, int v);

}  // namespace omnitune
