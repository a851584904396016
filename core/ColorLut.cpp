#include "core/ColorLut.h"

#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace omnitune {

std::array<HsvRange, kColorClassCount> ColorLutOptions::defaultRanges()
{
    std::array<HsvRange, kColorClassCount> r{};
    r[std::size_t(ColorClass::Unknown)] = HsvRange{false, 0, 179, 0, 255, 0, 255};
    r[std::size_t(ColorClass::Black)] = HsvRange{true, 0, 179, 0, 255, 0, 60};
    r[std::size_t(ColorClass::White)] = HsvRange{true, 0, 179, 0, 50, 170, 255};
    r[std::size_t(ColorClass::Green)] = HsvRange{true, 35, 85, 60, 255, 40, 255};
    r[std::size_t(ColorClass::Orange)] = HsvRange{true, 5, 22, 120, 255, 80, 255};
    r[std::size_t(ColorClass::Cyan)] = HsvRange{true, 86, 105, 120, 255, 80, 255};
    r[std::size_t(ColorClass::Magenta)] = HsvRange{true, 140, 170, 100, 255, 80, 255};
    return r;
}

ColorClass classifyHsv(const std::array<HsvRange, kColorClassCount>& ranges, int h, int s, int v)
{
    for (ColorClass c : kClassificationOrder)
        if (ranges[std::size_t(c)].contains(h, s, v)) return c;
    return ColorClass::Unknown;
}

std::array<std::uint8_t, 3> yuvToBgr(int y, int u, int v)
{
    const double du = u - 128.0;
    const double dv = v - 128.0;
    const double r = y + 1.402 * dv;
    const double g = y - 0.344136 * du - 0.714136 * dv;
    const double b = y + 1.772 * du;
    return {cv::saturate_cast<std::uint8_t>(b), cv::saturate_cast<std::uint8_t>(g),
            cv::saturate_cast<std::uint8_t>(r)};
}

void convertUyvyToBgr(const cv::Mat& uyvy, cv::Mat& bgr)
{
    CV_Assert(uyvy.type() == CV_8UC2 && uyvy.cols % 2 == 0);
    bgr.create(uyvy.size(), CV_8UC3);
    for (int y = 0; y < uyvy.rows; ++y) {
        const std::uint8_t* in = uyvy.ptr<std::uint8_t>(y);
        std::uint8_t* out = bgr.ptr<std::uint8_t>(y);
        for (int x = 0; x < uyvy.cols; x += 2, in += 4, out += 6) {
            const auto p0 = yuvToBgr(in[1], in[0], in[2]);
            const auto p1 = yuvToBgr(in[3], in[0], in[2]);
            std::copy(p0.begin(), p0.end(), out);
            std::copy(p1.begin(), p1.end(), out + 3);
        }
    }
}

void ColorLut::compile(const ColorLutOptions& options)
{
    // colors.lut_bits is checked once, by checkConfig(); this guards the table size and shifts.
    CV_Assert(options.bits >= 4 && options.bits <= 8);
    bits_ = options.bits;
    shift_ = 8 - bits_;
    const int levels = 1 << bits_;
    const int half = (1 << shift_) / 2;  // each entry stands for the centre of its bin
    const int entries = levels * levels * levels;

    // Every bin centre as a BGR pixel (for the YUV table: converted from YUV first), then
    // one cvtColor for all of them, so the table agrees with OpenCV's own HSV conversion.
    cv::Mat bgrGrid(1, entries, CV_8UC3);
    cv::Mat yuvGrid(1, entries, CV_8UC3);
    for (int i = 0; i < entries; ++i) {
        const int a = ((i >> (2 * bits_)) & (levels - 1)) << shift_;
        const int b = ((i >> bits_) & (levels - 1)) << shift_;
        const int c = (i & (levels - 1)) << shift_;
        auto& g = bgrGrid.at<cv::Vec3b>(0, i);
        g = cv::Vec3b(std::uint8_t(a + half), std::uint8_t(b + half), std::uint8_t(c + half));
        const auto yuv = yuvToBgr(a + half, b + half, c + half);
        yuvGrid.at<cv::Vec3b>(0, i) = cv::Vec3b(yuv[0], yuv[1], yuv[2]);
    }
    cv::Mat bgrHsv;
    cv::Mat yuvHsv;
    cv::cvtColor(bgrGrid, bgrHsv, cv::COLOR_BGR2HSV);
    cv::cvtColor(yuvGrid, yuvHsv, cv::COLOR_BGR2HSV);
    // Relative black: the table holds the class without black and without green's V floor,
    // with the V band beside it; segment() decides black per frame.
    relative_ = options.blackRelative;
    blackVRatio_ = options.blackVRatio;
    const HsvRange& black = options.ranges[std::size_t(ColorClass::Black)];
    fallbackBlackV_ = black.enabled ? black.vMax : -1;
    auto ranges = options.ranges;
    if (relative_) {
        ranges[std::size_t(ColorClass::Black)].enabled = false;
        ranges[std::size_t(ColorClass::Green)].vMin = 0;
    }
    auto entry = [&](const cv::Vec3b& hsv) {
        const auto cls = std::uint8_t(classifyHsv(ranges, hsv[0], hsv[1], hsv[2]));
        return relative_ ? std::uint8_t((cls << kBandBits) | (hsv[2] >> 3)) : cls;
    };
    bgrTable_.assign(std::size_t(entries), 0);
    yuvTable_.assign(std::size_t(entries), 0);
    for (int i = 0; i < entries; ++i) {
        bgrTable_[std::size_t(i)] = entry(bgrHsv.at<cv::Vec3b>(0, i));
        yuvTable_[std::size_t(i)] = entry(yuvHsv.at<cv::Vec3b>(0, i));
    }
    if (relative_) {
        fixedRemap_ = remapFor(fallbackBlackV_);
    } else {
        for (int b = 0; b < 256; ++b) fixedRemap_[std::size_t(b)] = std::uint8_t(b);
    }
}

std::array<std::uint8_t, 256> ColorLut::remapFor(int blackV) const
{
    std::array<std::uint8_t, 256> remap{};
    for (int b = 0; b < 256; ++b) {
        const int cls = b >> kBandBits;
        const int bandCentre = ((b & ((1 << kBandBits) - 1)) << 3) + 4;
        remap[std::size_t(b)] = bandCentre <= blackV ? std::uint8_t(ColorClass::Black) : std::uint8_t(cls);
    }
    return remap;
}

void ColorLut::segment(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans,
                       cv::Mat& classes, SegmentStats* stats) const
{
    CV_Assert(!empty());
    CV_Assert(classes.type() == CV_8UC1 && classes.size() == frame.size());
    if (format == PixelFormat::Bgr8) {
        CV_Assert(frame.type() == CV_8UC3);
        for (const RowSpan& s : spans) {
            const std::uint8_t* in = frame.ptr<std::uint8_t>(s.y) + 3 * s.x0;
            std::uint8_t* out = classes.ptr<std::uint8_t>(s.y);
            for (int x = s.x0; x < s.x1; ++x, in += 3)
                out[x] = bgrTable_[index(in[0], in[1], in[2])];
        }
    } else {
        CV_Assert(frame.type() == CV_8UC2);
        for (const RowSpan& s : spans) {
            const std::uint8_t* row = frame.ptr<std::uint8_t>(s.y);
            std::uint8_t* out = classes.ptr<std::uint8_t>(s.y);
            for (int x = s.x0; x < s.x1; ++x) {
                // Pixel pair (x & ~1, x | 1) shares U and V: U0 Y0 V0 Y1.
                const std::uint8_t* pair = row + 2 * (x & ~1);
                const std::uint8_t y = (x & 1) ? pair[3] : pair[1];
                out[x] = yuvTable_[index(y, pair[0], pair[2])];
            }
        }
    }
    if (stats) *stats = SegmentStats{};
    if (!relative_) return;

    // The carpet's V: median V band of the green pixels on every 4th row, every 2nd column
    // (~1/8 of the ring: enough for a median, cheap next to the table reads).
    std::array<int, 1 << kBandBits> bands{};
    const int greenCode = int(ColorClass::Green);
    for (const RowSpan& s : spans) {
        if (s.y & 3) continue;
        const std::uint8_t* row = classes.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; x += 2)
            if ((row[x] >> kBandBits) == greenCode) ++bands[std::size_t(row[x] & ((1 << kBandBits) - 1))];
    }
    int total = 0;
    for (int n : bands) total += n;
    int carpetV = -1;
    int blackV = fallbackBlackV_;
    // Too few carpet pixels to say how bright it is (a frame of robots, a covered lens).
    constexpr int kMinCarpetSamples = 32;
    if (total >= kMinCarpetSamples && fallbackBlackV_ >= 0) {
        int seen = 0;
        int band = 0;
        while (band < int(bands.size()) - 1 && (seen += bands[std::size_t(band)]) * 2 < total) ++band;
        carpetV = (band << 3) + 4;
        blackV = int(std::lround(blackVRatio_ * carpetV));
    }
    const std::array<std::uint8_t, 256> remap = remapFor(blackV);
    for (const RowSpan& s : spans) {
        std::uint8_t* out = classes.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) out[x] = remap[out[x]];
    }
    if (stats) *stats = SegmentStats{carpetV, blackV};
}

}  // namespace omnitune
