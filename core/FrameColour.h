#pragma once
// The camera frame's colour at single pixels, read on demand in either pixel format, as BGR or
// as OpenCV's 8-bit HSV (H 0..179). Validation reads a few hundred pixels per candidate, so it
// converts those and never the whole frame.
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <array>
#include <cstdint>

namespace omnitune {

struct Hsv {
    int h = 0;  // 0..179 (OpenCV's 8-bit hue)
    int s = 0;  // 0..255
    int v = 0;  // 0..255
};

// OpenCV's 8-bit BGR -> HSV for one pixel.
Hsv bgrToHsv(std::uint8_t b, std::uint8_t g, std::uint8_t r);

class FrameColour {
public:
    // `frame` must outlive this view (CV_8UC3 for Bgr8, CV_8UC2 for Uyvy).
    FrameColour(const cv::Mat& frame, PixelFormat format) : frame_(frame), format_(format) {}

    const cv::Mat& frame() const { return frame_; }
    std::array<std::uint8_t, 3> bgrAt(int x, int y) const;
    Hsv hsvAt(int x, int y) const
    {
        const auto c = bgrAt(x, y);
        return bgrToHsv(c[0], c[1], c[2]);
    }
    // 8-bit luma (BT.601), for edge profiles.
    int grayAt(int x, int y) const
    {
        const auto c = bgrAt(x, y);
        return (29 * c[0] + 150 * c[1] + 77 * c[2] + 128) >> 8;
    }

private:
    const cv::Mat& frame_;
    PixelFormat format_;
};

}  // namespace omnitune
