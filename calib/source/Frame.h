#pragma once
// One image from a frame source, with what the pipeline and the GUI need to know about it.
#include "core/CameraSettings.h"
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <optional>

namespace omnitune {

struct Frame {
    cv::Mat image;                          // CV_8UC3 for Bgr8, CV_8UC2 for Uyvy
    PixelFormat format = PixelFormat::Bgr8;
    int index = -1;                         // 0-based position in the source; counts up on a live camera
    double timestampS = 0.0;                // s since the source's first frame
    std::optional<CameraSettings> camera;   // the settings it was taken with, when the source knows them
};

}  // namespace omnitune
