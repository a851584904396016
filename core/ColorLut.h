#pragma once
// Colour look-up table: maps a pixel colour straight to its colour class, replacing the HSV
// conversion and range tests per pixel by one array read (thesis ch. 4, "visionTh").
#include "core/ColorClass.h"
#include "core/HsvRange.h"
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace omnitune {

struct RowSpan;

struct ColorLutOptions {
    // HSV range of each class, indexed by ColorClass (Unknown's entry is unused).
    std::array<HsvRange, kColorClassCount> ranges = defaultRanges();
    // Index bits per colour channel; the table has 2^(3*bits) entries (6 -> 256 KiB, in L2).
    // Fewer bits: smaller, faster table, coarser class boundaries. Range 4..8.
    int bits = 6;

    static std::array<HsvRange, kColorClassCount> defaultRanges();
};

// Direct classification of one HSV triple, in kClassificationOrder.
ColorClass classifyHsv(const std::array<HsvRange, kColorClassCount>& ranges, int h, int s, int v);

// Full-range BT.601 YUV -> BGR as libdc1394 converts it; used to build the UYVY table and to
// display UYVY frames, so both agree.
std::array<std::uint8_t, 3> yuvToBgr(int y, int u, int v);
void convertUyvyToBgr(const cv::Mat& uyvy, cv::Mat& bgr);

class ColorLut {
public:
    ColorLut() = default;
    explicit ColorLut(const ColorLutOptions& options) { compile(options); }

    // Builds both tables (BGR- and YUV-indexed). Cost: one cvtColor over 2^(3*bits) colours.
    void compile(const ColorLutOptions& options);
    bool empty() const { return bgrTable_.empty(); }
    int bits() const { return bits_; }

    ColorClass classifyBgr(std::uint8_t b, std::uint8_t g, std::uint8_t r) const
    {
        return static_cast<ColorClass>(bgrTable_[index(b, g, r)]);
    }
    ColorClass classifyYuv(std::uint8_t y, std::uint8_t u, std::uint8_t v) const
    {
        return static_cast<ColorClass>(yuvTable_[index(y, u, v)]);
    }

    // Segments the pixels inside `spans` into class ids (CV_8UC1, same size as the frame);
    // pixels outside the spans are left as they are (callers keep them Unknown).
    void segment(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans,
                 cv::Mat& classes) const;

private:
    std::size_t index(std::uint8_t a, std::uint8_t b, std::uint8_t c) const
    {
        return (std::size_t(a >> shift_) << (2 * bits_)) | (std::size_t(b >> shift_) << bits_) |
               std::size_t(c >> shift_);
    }

    int bits_ = 0;
    int shift_ = 0;
    std::vector<std::uint8_t> bgrTable_;
    std::vector<std::uint8_t> yuvTable_;
};

}  // namespace omnitune
