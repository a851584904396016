#include "core/FrameNoise.h"

#include "core/Geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace omnitune {

namespace {

struct BgrGreen {
    int operator()(const std::uint8_t* row, int x) const { return row[3 * x + 1]; }
};

// UYVY: U0 Y0 V0 Y1 per pair; G = Y - 0.344136 (U - 128) - 0.714136 (V - 128), in Q8.
struct UyvyGreen {
    int operator()(const std::uint8_t* row, int x) const
    {
        const std::uint8_t* pair = row + 4 * (x >> 1);
        return pair[1 + 2 * (x & 1)] - (88 * (pair[0] - 128) + 183 * (pair[2] - 128)) / 256;
    }
};

template <typename Green>
double noiseSigma(const cv::Mat& frame, const std::vector<RowSpan>& spans, Green green)
{
    std::int64_t sum = 0;
    std::int64_t count = 0;
    for (const RowSpan& s : spans) {
        if (s.y < 1 || s.y >= frame.rows - 1 || (s.y & 3)) continue;
        const std::uint8_t* up = frame.ptr<std::uint8_t>(s.y - 1);
        const std::uint8_t* mid = frame.ptr<std::uint8_t>(s.y);
        const std::uint8_t* down = frame.ptr<std::uint8_t>(s.y + 1);
        const int x0 = std::max(1, s.x0);
        const int x1 = std::min(frame.cols - 1, s.x1);
        for (int x = x0; x < x1; ++x) {
            const int l = x - 1;
            const int r = x + 1;
            // Kernel [1 -2 1; -2 4 -2; 1 -2 1].
            const int v = green(up, l) - 2 * green(up, x) + green(up, r) -
                          2 * (green(mid, l) - 2 * green(mid, x) + green(mid, r)) + green(down, l) -
                          2 * green(down, x) + green(down, r);
            sum += std::abs(v);
        }
        count += std::max(0, x1 - x0);
    }
    if (count == 0) return 0.0;
    // sigma = sqrt(pi / 2) / 6 x mean |kernel response| (the kernel's L2 norm is 6).
    return std::sqrt(M_PI / 2.0) / 6.0 * double(sum) / double(count);
}

}  // namespace

double frameNoiseSigma(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans)
{
    if (format == PixelFormat::Bgr8) {
        CV_Assert(frame.type() == CV_8UC3);
        return noiseSigma(frame, spans, BgrGreen{});
    }
    CV_Assert(frame.type() == CV_8UC2 && frame.cols % 2 == 0);
    return noiseSigma(frame, spans, UyvyGreen{});
}

}  // namespace omnitune
