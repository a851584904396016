#include "core/ColorLut.h"

#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace omnitune {

bool operator==(const ColorLutOptions& a, const ColorLutOptions& b)
{
    return a.classes == b.classes && a.bits == b.bits && a.blackRelative == b.blackRelative &&
           a.blackVRatio == b.blackVRatio && a.sampleOutlierPct == b.sampleOutlierPct;
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
    // Relative black: the table holds the class without the black classes and without the field
    // classes' V floor; segment() decides black per frame from each pixel's V band.
    relative_ = options.blackRelative;
    blackVRatio_ = options.blackVRatio;
    fallbackBlackV_ = -1;
    blackId_ = 0;
    fieldMask_ = 0;
    ColourClasses classes = options.classes;
    for (std::size_t i = 0; i < classes.size() && i < std::size_t(kMaxColourClasses); ++i) {
        ColourClassDef& c = classes[i];
        if (c.role == ColourRole::Field) fieldMask_ |= 1u << (i + 1);
        if (c.role == ColourRole::Black && c.enabled) {
            if (blackId_ == 0) blackId_ = std::uint8_t(i + 1);
            for (const HsvRange& box : c.boxes)
                if (box.enabled) fallbackBlackV_ = std::max(fallbackBlackV_, box.vMax);
        }
        if (!relative_) continue;
        if (c.role == ColourRole::Black) c.enabled = false;
        if (c.role == ColourRole::Field)
            for (HsvRange& box : c.boxes) box.vMin = 0;
    }
    if (blackId_ == 0) fallbackBlackV_ = -1;
    for (int v = 0; v < 256; ++v) vBand_[std::size_t(v)] = std::uint8_t((((v >> shift_) << shift_) + half) >> 3);
    bgrTable_.assign(std::size_t(entries), 0);
    yuvTable_.assign(std::size_t(entries), 0);
    yuvBand_.assign(relative_ ? std::size_t(entries) : 0, 0);
    for (int i = 0; i < entries; ++i) {
        const cv::Vec3b& h = bgrHsv.at<cv::Vec3b>(0, i);
        bgrTable_[std::size_t(i)] = std::uint8_t(classifyHsv(classes, h[0], h[1], h[2]));
        const cv::Vec3b& y = yuvHsv.at<cv::Vec3b>(0, i);
        yuvTable_[std::size_t(i)] = std::uint8_t(classifyHsv(classes, y[0], y[1], y[2]));
        if (relative_) yuvBand_[std::size_t(i)] = std::uint8_t(y[2] >> 3);
    }
}

std::vector<std::uint8_t> ColorLut::bgrTable() const
{
    std::vector<std::uint8_t> out = bgrTable_;
    if (!relative_) return out;
    const int levels = 1 << bits_;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const int b = int((i >> (2 * bits_)) & std::size_t(levels - 1)) << shift_;
        const int g = int((i >> bits_) & std::size_t(levels - 1)) << shift_;
        const int r = int(i & std::size_t(levels - 1)) << shift_;
        out[i] = std::uint8_t(classifyBgr(std::uint8_t(b), std::uint8_t(g), std::uint8_t(r)));
    }
    return out;
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

    // The carpet's V: median V band of the field pixels on every 4th row, every 2nd column
    // (~1/8 of the ring: enough for a median, cheap next to the table reads). A pixel's V band
    // comes from its largest channel (BGR) or from a second table (UYVY).
    const bool bgr = format == PixelFormat::Bgr8;
    auto uyvyBand = [this](const std::uint8_t* row, int x) {
        const std::uint8_t* pair = row + 2 * (x & ~1);
        return yuvBand_[index((x & 1) ? pair[3] : pair[1], pair[0], pair[2])];
    };
    std::array<int, 32> bands{};
    for (const RowSpan& s : spans) {
        if (s.y & 3) continue;
        const std::uint8_t* cls = classes.ptr<std::uint8_t>(s.y);
        const std::uint8_t* row = frame.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; x += 2) {
            if (!((fieldMask_ >> cls[x]) & 1u)) continue;
            const std::uint8_t* p = row + 3 * x;
            ++bands[bgr ? vBand_[std::max(p[0], std::max(p[1], p[2]))] : uyvyBand(row, x)];
        }
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
    if (blackV >= 0 && bgr) {
        // Black by the largest channel directly: one 256-entry look-up per pixel.
        std::array<std::uint8_t, 256> dark{};
        for (int v = 0; v < 256; ++v) dark[std::size_t(v)] = isBlackBand(vBand_[std::size_t(v)], blackV);
        for (const RowSpan& s : spans) {
            const std::uint8_t* in = frame.ptr<std::uint8_t>(s.y) + 3 * s.x0;
            std::uint8_t* out = classes.ptr<std::uint8_t>(s.y);
            for (int x = s.x0; x < s.x1; ++x, in += 3)
                if (dark[std::max(in[0], std::max(in[1], in[2]))]) out[x] = blackId_;
        }
    } else if (blackV >= 0) {
        std::array<bool, 32> dark{};
        for (int b = 0; b < 32; ++b) dark[std::size_t(b)] = isBlackBand(b, blackV);
        for (const RowSpan& s : spans) {
            const std::uint8_t* row = frame.ptr<std::uint8_t>(s.y);
            std::uint8_t* out = classes.ptr<std::uint8_t>(s.y);
            for (int x = s.x0; x < s.x1; ++x)
                if (dark[uyvyBand(row, x)]) out[x] = blackId_;
        }
    }
    if (stats) *stats = SegmentStats{carpetV, blackV};
}

}  // namespace omnitune
