#pragma once
// The colours of sampled pixels: what a click, brush or rectangle on a pane contributes to a
// colour class. Pixels the detector never processes (mask, outside the mirror ring) are not
// samples; they are counted so the window can say how many were ignored.
#include "core/FrameColour.h"
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

struct ColourSamples {
    std::vector<Hsv> hsv;  // one per processed sampled pixel
    int masked = 0;        // sampled pixels outside the processed area, ignored

    void append(const ColourSamples& more);
};

// HSV of `pixels` of `frame` (Bgr8 or Uyvy) where `used` (CV_8UC1 of the frame's size, non-zero
// = processed; empty = every pixel) allows. Pixels outside the frame are skipped silently.
ColourSamples sampleColours(const cv::Mat& frame, PixelFormat format, const cv::Mat& used,
                            const std::vector<cv::Point>& pixels);

}  // namespace omnitune
