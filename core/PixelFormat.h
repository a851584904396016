#pragma once
// Pixel layouts a frame can arrive in.
#include <string_view>

namespace omnitune {

enum class PixelFormat {
    Bgr8,  // CV_8UC3, OpenCV's usual order
    Uyvy,  // CV_8UC2, YUV 4:2:2 as IIDC firewire cameras deliver it: U0 Y0 V0 Y1 per pixel pair
};

inline std::string_view pixelFormatName(PixelFormat f) { return f == PixelFormat::Bgr8 ? "bgr8" : "uyvy"; }

}  // namespace omnitune
