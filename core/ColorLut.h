#pragma once
// Colour look-up table: maps a pixel colour straight to its colour class, replacing the HSV
// conversion and range tests per pixel by one array read (thesis ch. 4, "visionTh").
#include "core/ColorClass.h"
#include "core/ColourClasses.h"
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace omnitune {

struct RowSpan;

struct ColorLutOptions {
    // The classes in priority order (core/ColourClasses.h); ids 1..N in the segmented image.
    ColourClasses classes = defaultColourClasses();
    // Index bits per colour channel; the table has 2^(3*bits) entries (6 -> 256 KiB, in L2).
    // Fewer bits: smaller, faster table, coarser class boundaries. Range 4..8.
    int bits = 6;
    // Black relative to the frame's carpet (ours; thesis: off, black is the fixed V range of
    // the black classes' boxes). On, a pixel is black (the first class with role black) when its
    // V is at most blackVRatio times the median V of the frame's carpet (pixels in a field
    // class's H/S boxes), whatever its hue; the black classes' boxes and the field classes' V
    // floors are then not used (the highest V max of the black boxes serves only when a frame
    // shows no carpet).
    // Why: in dim light a fixed V <= 60 turns the carpet itself into black speckle (simulated
    // dim tours: 0-2 % of balls found with the thesis' black, 82-90 % with relative black, no
    // change in normal and bright light), hence on by default.
    bool blackRelative = true;
    double blackVRatio = 0.45;
    // Not used by the table: the share of a sampling stroke's colours ignored at each end of H,
    // S and V when the Colours tab grows a box (calib/colour/BoxFit.h's outlierPct). Ours: 1 %
    // keeps a brush stroke's blurred ball rim from stretching the ball's box.
    double sampleOutlierPct = 1.0;
};
bool operator==(const ColorLutOptions& a, const ColorLutOptions& b);
inline bool operator!=(const ColorLutOptions& a, const ColorLutOptions& b) { return !(a == b); }

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
    // Whether class `id` has role field (the carpet).
    bool isField(ColorClass id) const { return std::uint8_t(id) < 32 && ((fieldMask_ >> std::uint8_t(id)) & 1u); }

    // One colour's class. With relative black, as if the carpet's V were unknown (black up to
    // the black boxes' V max); segment() uses the frame's carpet instead.
    ColorClass classifyBgr(std::uint8_t b, std::uint8_t g, std::uint8_t r) const
    {
        const std::uint8_t cls = bgrTable_[index(b, g, r)];
        return static_cast<ColorClass>(relative_ && isBlackBand(bgrBand(b, g, r), fallbackBlackV_) ? blackId_ : cls);
    }
    ColorClass classifyYuv(std::uint8_t y, std::uint8_t u, std::uint8_t v) const
    {
        const std::size_t i = index(y, u, v);
        return static_cast<ColorClass>(relative_ && isBlackBand(yuvBand_[i], fallbackBlackV_) ? blackId_ : yuvTable_[i]);
    }

    // The compiled BGR table: one class id per entry, entry (b >> s) << 2*bits | (g >> s) << bits
    // | (r >> s) with s = 8 - bits; with relative black, as classifyBgr() gives it (black classes
    // up to the fallback V). What --export-lut writes.
    std::vector<std::uint8_t> bgrTable() const;

    // Segments the pixels inside `spans` into class ids (CV_8UC1, same size as the frame);
    // pixels outside the spans are left as they are (callers keep them Unknown). With relative
    // black: one table read per pixel, the carpet's V from a subsampled histogram of the field
    // pixels' V bands, then a second pass that makes the pixels at or below black V black.
    void segment(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans,
                 cv::Mat& classes, SegmentStats* stats = nullptr) const;

private:
    std::size_t index(std::uint8_t a, std::uint8_t b, std::uint8_t c) const
    {
        return (std::size_t(a >> shift_) << (2 * bits_)) | (std::size_t(b >> shift_) << bits_) |
               std::size_t(c >> shift_);
    }

    // Relative black decides per pixel from its V band (V >> 3 of the table entry's colour):
    // black when the band's centre is at most the frame's black V.
    static bool isBlackBand(int band, int blackV) { return (band << 3) + 4 <= blackV; }
    // V of a BGR entry's colour is the largest channel of its bin centre (OpenCV's HSV V).
    int bgrBand(std::uint8_t b, std::uint8_t g, std::uint8_t r) const
    {
        return vBand_[std::max(b, std::max(g, r))];
    }

    int bits_ = 0;
    int shift_ = 0;
    bool relative_ = false;
    double blackVRatio_ = 0.0;
    int fallbackBlackV_ = 60;    // the black boxes' highest V max, -1: no black class
    std::uint8_t blackId_ = 0;   // the first enabled class with role black
    std::uint32_t fieldMask_ = 0;  // bit id: class id has role field (the carpet)
    std::array<std::uint8_t, 256> vBand_{};  // channel value -> V band of its bin centre
    std::vector<std::uint8_t> bgrTable_;
    std::vector<std::uint8_t> yuvTable_;
    std::vector<std::uint8_t> yuvBand_;  // relative black: the V band of each YUV entry
};

}  // namespace omnitune
