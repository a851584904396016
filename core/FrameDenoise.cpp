#include "core/FrameDenoise.h"

#include "core/FrameNoise.h"
#include "core/Geometry.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

FrameDenoiser::FrameDenoiser(const DenoiseOptions& options) : options_(options)
{
    // The 3x3 Gaussian is separable: (e, 1, e) / (1 + 2e) with e = exp(-1 / (2 sigma^2)), in 8-bit
    // fixed point per pass.
    const double sigma = std::max(1e-3, options.blurSigma);
    const double e = std::exp(-1.0 / (2.0 * sigma * sigma));
    side_ = int(std::lround(256.0 * e / (1.0 + 2.0 * e)));
    // UYVY's U and V samples lie 2 px apart along a row: the same sigma spans half as many of them.
    const double ec = std::pow(e, 4.0);
    chromaSide_ = int(std::lround(256.0 * ec / (1.0 + 2.0 * ec)));
}

const cv::Mat& FrameDenoiser::apply(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans)
{
    lastNoise_ = 0.0;
    lastBlurred_ = false;
    if (options_.aboveNoise <= 0.0) return frame;
    lastNoise_ = frameNoiseSigma(frame, format, spans);
    if (lastNoise_ <= options_.aboveNoise) return frame;
    blur(frame, format);
    lastBlurred_ = true;
    return blurred_;
}

void FrameDenoiser::blur(const cv::Mat& frame, PixelFormat format)
{
    const bool uyvy = format == PixelFormat::Uyvy;
    CV_Assert(uyvy ? frame.type() == CV_8UC2 && frame.cols % 2 == 0 : frame.type() == CV_8UC3);
    // UYVY: only U and V are blurred. Colour noise is what turns carpet pixels into other
    // classes; Y keeps a far ball's outline sharp. Optics matrix read as UYVY, seeds 1-8,
    // combined: U and V 5609 balls / 51 false-positive frames, Y too 5604 / 56, Y alone 5577 /
    // 52, no blur 5591 / 52 (docs/evaluation.md, thirty-fourth session).
    const int h = frame.rows;
    const int n = frame.cols * frame.channels();  // values per row
    blurred_.create(frame.size(), frame.type());
    rows_.resize(3 * std::size_t(n));
    const unsigned side = unsigned(side_);
    const unsigned centre = 256u - 2u * side;
    const unsigned chromaSide = unsigned(chromaSide_);
    const unsigned chromaCentre = 256u - 2u * chromaSide;

    // Row y's horizontal pass lives in the ring slot y % 3.
    auto slot = [&](int y) { return rows_.data() + std::size_t(y % 3) * std::size_t(n); };
    // The horizontal pass of row y into its slot (border replicated). BGR: a pixel's neighbours
    // are 3 values away. UYVY (U0 Y0 V0 Y1): a U's or V's are 4 away, the next pair's.
    auto horizontal = [&](int y) {
        const std::uint8_t* in = frame.ptr<std::uint8_t>(y);
        std::uint16_t* out = slot(y);
        if (uyvy) {
            // U and V only (the Y values, 1 and 3 of each pair, are not blurred: see blur()).
            for (int b = 0; b < n; b += 4) {
                const int prev = b >= 4 ? b - 4 : b;     // the pair before (replicated at the border)
                const int next = b + 4 < n ? b + 4 : b;  // the pair after
                for (int k : {b, b + 2})
                    out[k] = std::uint16_t(chromaSide * in[k - b + prev] + chromaCentre * in[k] + chromaSide * in[k - b + next]);
            }
            return;
        }
        auto at = [&](int i) {
            const int l = i >= 3 ? i - 3 : i;
            const int r = i + 3 < n ? i + 3 : i;
            return std::uint16_t(side * in[l] + centre * in[i] + side * in[r]);
        };
        const int edge = std::min(3, n);
        for (int i = 0; i < edge; ++i) out[i] = at(i);
        for (int i = 3; i < n - 3; ++i) out[i] = std::uint16_t(side * in[i - 3] + centre * in[i] + side * in[i + 3]);
        for (int i = std::max(edge, n - 3); i < n; ++i) out[i] = at(i);
    };

    horizontal(0);
    if (h > 1) horizontal(1);
    for (int y = 0; y < h; ++y) {
        if (y + 1 < h && y + 1 >= 2) horizontal(y + 1);  // overwrites row y - 2, no longer needed
        const std::uint16_t* up = slot(std::max(y - 1, 0));
        const std::uint16_t* mid = slot(y);
        const std::uint16_t* down = slot(std::min(y + 1, h - 1));
        std::uint8_t* out = blurred_.ptr<std::uint8_t>(y);
        if (uyvy) {
            const std::uint8_t* in = frame.ptr<std::uint8_t>(y);
            for (int i = 0; i < n; i += 2) {
                out[i] = std::uint8_t((side * up[i] + centre * mid[i] + side * down[i] + 32768u) >> 16);
                out[i + 1] = in[i + 1];
            }
            continue;
        }
        for (int i = 0; i < n; ++i)
            out[i] = std::uint8_t((side * up[i] + centre * mid[i] + side * down[i] + 32768u) >> 16);
    }
}

}  // namespace omnitune
