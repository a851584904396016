#include "core/Edges.h"

#include "core/FillBytes.h"
#include "core/Geometry.h"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace omnitune {

std::string_view edgeInputName(EdgeInput input)
{
    return input == EdgeInput::Gray ? "gray" : "binary";
}

std::optional<EdgeInput> parseEdgeInput(std::string_view name)
{
    if (name == "binary") return EdgeInput::Binary;
    if (name == "gray") return EdgeInput::Gray;
    return std::nullopt;
}

void makeBinary(const cv::Mat& classes, const Geometry& geometry, cv::Mat& binary, int whiteLevel,
                const ColourRoles& roles)
{
    CV_Assert(classes.type() == CV_8UC1);
    binary.create(classes.size(), CV_8UC1);
    fillBytes(binary, 255);
    const auto whiteOut = std::uint8_t(binaryWhiteLevel(whiteLevel));
    std::array<std::uint8_t, 256> level{};  // class id -> binary value
    for (int id = 0; id < 256; ++id)
        level[std::size_t(id)] = roles.field(std::uint8_t(id)) ? 255 : roles.line(std::uint8_t(id)) ? whiteOut : 0;
    for (const RowSpan& s : geometry.spans()) {
        const std::uint8_t* in = classes.ptr<std::uint8_t>(s.y);
        std::uint8_t* out = binary.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) out[x] = level[in[x]];
    }
}

void makeGray(const cv::Mat& frame, bool uyvy, cv::Mat& gray)
{
    gray.create(frame.size(), CV_8UC1);
    if (!uyvy) {
        CV_Assert(frame.type() == CV_8UC3);
        // BT.601 luma in 8-bit fixed point (weights sum to 256), as cvtColor would, without its
        // per-call allocation.
        for (int y = 0; y < frame.rows; ++y) {
            const std::uint8_t* in = frame.ptr<std::uint8_t>(y);
            std::uint8_t* out = gray.ptr<std::uint8_t>(y);
            for (int x = 0; x < frame.cols; ++x, in += 3)
                out[x] = std::uint8_t((29 * in[0] + 150 * in[1] + 77 * in[2] + 128) >> 8);
        }
        return;
    }
    CV_Assert(frame.type() == CV_8UC2);
    for (int y = 0; y < frame.rows; ++y) {
        const std::uint8_t* in = frame.ptr<std::uint8_t>(y);
        std::uint8_t* out = gray.ptr<std::uint8_t>(y);
        for (int x = 0; x < frame.cols; ++x) out[x] = in[2 * x + 1];  // U Y V Y: Y at odd bytes
    }
}

namespace {
// tan(22.5 deg) in 15-bit fixed point, as in OpenCV's Canny, so that directions match it.
constexpr int kShift = 15;
constexpr int kTan22 = 13573;

// The 3x3 Sobel derivatives at x of the row `mid` between `up` and `down` (replicated border:
// the caller passes the clamped rows, `l` and `r` the clamped columns).
struct Gradient {
    int gx;
    int gy;
};
inline Gradient sobelAt(const std::uint8_t* up, const std::uint8_t* mid, const std::uint8_t* down, int x, int l, int r)
{
    return {(up[r] + 2 * mid[r] + down[r]) - (up[l] + 2 * mid[l] + down[l]),
            (down[l] + 2 * down[x] + down[r]) - (up[l] + 2 * up[x] + up[r])};
}

}  // namespace

void CannyDetector::detect(const cv::Mat& gray, const EdgeOptions& options, cv::Mat& edges)
{
    CV_Assert(gray.type() == CV_8UC1);
    const int w = gray.cols;
    const int h = gray.rows;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    const int stride = w + 2;  // magnitude_ has a zero border: neighbours need no bounds checks
    if (size_ != gray.size()) {
        magnitude_.assign(std::size_t(stride) * std::size_t(h + 2), 0);
        size_ = gray.size();
    }
    state_.resize(n);
    if (stack_.capacity() < n) stack_.reserve(n);
    stack_.clear();
    auto row = [&](int y) { return gray.ptr<std::uint8_t>(std::clamp(y, 0, h - 1)); };

    // 3x3 Sobel with a replicated border, L1 magnitude only: the few pixels above the low
    // threshold recompute their derivatives below. The inner columns need no clamping, which
    // lets the compiler vectorise them.
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* up = row(y - 1);
        const std::uint8_t* mid = row(y);
        const std::uint8_t* down = row(y + 1);
        std::int16_t* magRow = magnitude_.data() + std::size_t(y + 1) * std::size_t(stride) + 1;
        auto magnitude = [&](int x, int l, int r) {
            const Gradient g = sobelAt(up, mid, down, x, l, r);
            return std::int16_t(std::abs(g.gx) + std::abs(g.gy));
        };
        magRow[0] = magnitude(0, 0, std::min(1, w - 1));
        for (int x = 1; x < w - 1; ++x) magRow[x] = magnitude(x, x - 1, x + 1);
        if (w > 1) magRow[w - 1] = magnitude(w - 1, w - 2, w - 1);
    }

    // Non-maximum suppression along the quantised gradient direction; outside the image the
    // magnitude counts as 0. state: 0 = no edge, 1 = weak (above low), 2 = strong (above high).
    const int low = options.cannyLow;
    const int high = options.cannyHigh;
    std::fill(state_.begin(), state_.end(), std::uint8_t(0));
    constexpr int kBlock = 16;  // runs of pixels at or below the low threshold are skipped a block at a time
    for (int y = 0; y < h; ++y) {
        const std::int16_t* m0 = magnitude_.data() + std::size_t(y + 1) * std::size_t(stride) + 1;
        const std::int16_t* mUp = m0 - stride;
        const std::int16_t* mDown = m0 + stride;
        const std::uint8_t* up = row(y - 1);
        const std::uint8_t* mid = row(y);
        const std::uint8_t* down = row(y + 1);
        const std::size_t rowStart = std::size_t(y) * std::size_t(w);
        for (int x = 0; x < w; ++x) {
            if (x + kBlock <= w) {
                bool any = false;
                for (int k = 0; k < kBlock; ++k) any |= m0[x + k] > low;
                if (!any) {
                    x += kBlock - 1;
                    continue;
                }
            }
            const int m = m0[x];
            if (m <= low) continue;
            const Gradient g = sobelAt(up, mid, down, x, std::max(x - 1, 0), std::min(x + 1, w - 1));
            const int ax = std::abs(g.gx);
            const int ay = std::abs(g.gy) << kShift;
            const int tg22x = ax * kTan22;
            bool isMax;
            if (ay < tg22x) {
                isMax = m > m0[x - 1] && m >= m0[x + 1];
            } else {
                const int tg67x = tg22x + (ax << (kShift + 1));
                if (ay > tg67x) {
                    isMax = m > mUp[x] && m >= mDown[x];
                } else {
                    const int s = (g.gx ^ g.gy) < 0 ? -1 : 1;
                    isMax = m > mUp[x - s] && m > mDown[x + s];
                }
            }
            if (!isMax) continue;
            const std::size_t i = rowStart + std::size_t(x);
            state_[i] = m > high ? 2 : 1;
            if (state_[i] == 2) stack_.push_back(int(i));
        }
    }

    // Hysteresis: grow strong edges into 8-connected weak ones.
    while (!stack_.empty()) {
        const int i = stack_.back();
        stack_.pop_back();
        const int x = i % w;
        const int y = i / w;
        for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, h - 1); ++ny) {
            for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, w - 1); ++nx) {
                const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                if (state_[j] == 1) {
                    state_[j] = 2;
                    stack_.push_back(int(j));
                }
            }
        }
    }

    edges.create(h, w, CV_8UC1);
    for (int y = 0; y < h; ++y) {
        std::uint8_t* out = edges.ptr<std::uint8_t>(y);
        const std::uint8_t* st = state_.data() + std::size_t(y) * std::size_t(w);
        for (int x = 0; x < w; ++x) out[x] = st[x] == 2 ? 255 : 0;
    }
}

}  // namespace omnitune
