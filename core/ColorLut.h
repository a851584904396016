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
    // Black relative to the frame's carpet (ours; thesis: off, black is the fixed V range of
    // ranges[Black]). On, a pixel is black when its V is at most blackVRatio times the median V
    // of the frame's carpet (pixels in green's H/S box), whatever its hue; green's and black's own
    // V bounds are then not used (ranges[Black].vMax serves only when a frame shows no carpet).
    // Why: in dim light a fixed V <= 60 turns the carpet itself into black speckle (simulated
    // dim tours: 0-2 % of balls found with the thesis' black, 82-90 % with relative black, no
    // change in normal and bright light), hence on by default.
    bool blackRelative = true;
    double blackVRatio = 0.45;

    static std::array<HsvRange, kColorClassCount> defaultRanges();
};

// Direct classification of one HSV triple, in kClassificationOrder.
ColorClass classifyHsv(const std::array<HsvRange, kColorClassCount>& ranges, int h, int s, int v);

// What segment() measured on the last frame (relative black only).
struct SegmentStats {
    int carpetV = -1;  // median V of the carpet's pixels, -1: no carpet seen (or relative black off)
    int blackV = -1;   // pixels with V up to this were black
};

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

    bool blackRelative() const { return relative_; }

    // One colour's class. With relative black, as if the carpet's V were unknown (black up to
    // ranges[Black].vMax); segment() uses the frame's carpet instead.
    ColorClass classifyBgr(std::uint8_t b, std::uint8_t g, std::uint8_t r) const
    {
        return static_cast<ColorClass>(fixedRemap_[bgrTable_[index(b, g, r)]]);
    }
    ColorClass classifyYuv(std::uint8_t y, std::uint8_t u, std::uint8_t v) const
    {
        return static_cast<ColorClass>(fixedRemap_[yuvTable_[index(y, u, v)]]);
    }

    // Segments the pixels inside `spans` into class ids (CV_8UC1, same size as the frame);
    // pixels outside the spans are left as they are (callers keep them Unknown). With relative
    // black: one table read per pixel into a (class, V band) byte, the carpet's V from a
    // subsampled histogram of those bytes, then one 256-entry remap per pixel.
    void segment(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans,
                 cv::Mat& classes, SegmentStats* stats = nullptr) const;

private:
    std::size_t index(std::uint8_t a, std::uint8_t b, std::uint8_t c) const
    {
        return (std::size_t(a >> shift_) << (2 * bits_)) | (std::size_t(b >> shift_) << bits_) |
               std::size_t(c >> shift_);
    }

    // Relative black: table entries are (class << kBandBits) | V band, V band = V >> 3.
    static constexpr int kBandBits = 5;
    // The class of every table byte when black is everything up to `blackV`.
    std::array<std::uint8_t, 256> remapFor(int blackV) const;

    int bits_ = 0;
    int shift_ = 0;
    bool relative_ = false;
    double blackVRatio_ = 0.0;
    int fallbackBlackV_ = 60;
    std::array<std::uint8_t, 256> fixedRemap_{};  // identity, or remapFor(fallbackBlackV_)
    std::vector<std::uint8_t> bgrTable_;
    std::vector<std::uint8_t> yuvTable_;
};

}  // namespace omnitune
