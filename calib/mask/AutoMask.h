#pragma once
// A first robot mask from frames in which the robot drives or turns (issue 11): the robot's own
// structure (body, mirror-support rods, reflections in the mirror) stays put in the image while
// the field moves under it. A pixel is proposed as "robot" when its colour stays within a
// tolerance of its own median in nearly every frame and that median is not carpet (a uniform
// carpet also stays put; it must be processed). The user edits the result.
#include "calib/fit/FitError.h"
#include "core/ColorLut.h"
#include "core/Geometry.h"
#include "core/Progress.h"

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace omnitune {

struct AutoMaskOptions {
    int minFrames = 4;              // fewer frames cannot tell still from moving
    double changeLevel = 20.0;      // grey levels (largest channel difference) from the pixel's median that count as a change
    double maxChangeShare = 0.10;   // a robot pixel changes in at most this share of the frames (noise, flicker)
    double minMovingShare = 0.01;   // share of the ring's pixels that must change, or the field did not move
    int openPx = 1;                 // px; specks thinner than this are dropped (a still line pixel, noise)
    int minRegionPx = 25;           // px; robot regions smaller than this are dropped
    int growPx = 2;                 // px; regions grow by this so their blurred borders never reach Canny
};

struct AutoMask {
    cv::Mat mask;             // CV_8UC1, 255 = process, 0 = robot (Config::mask convention)
    double robotShare = 0.0;  // share of the ring's pixels marked robot
    int regions = 0;          // connected robot regions kept
    int frames = 0;
};

struct AutoMaskResult {
    AutoMask fit;  // meaningful only when ok()
    std::optional<FitError> error;

    bool ok() const { return !error.has_value(); }
};

// `frames`: BGR (CV_8UC3) or UYVY (CV_8UC2), all of the geometry's size. Only pixels inside the
// geometry's outer radius are judged; pixels outside stay 255 (the ring already leaves them out).
// `lut` says which medians are carpet. `progress` may be null.
AutoMaskResult autoMask(const std::vector<cv::Mat>& frames, const GeometryOptions& geometry, const ColorLut& lut,
                        const AutoMaskOptions& options = {}, Progress* progress = nullptr);

}  // namespace omnitune
