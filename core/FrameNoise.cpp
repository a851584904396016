#include "core/FrameNoise.h"

#include "core/Geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace omnitune {

double frameNoiseSigma(const cv::Mat& bgr, const std::vector<RowSpan>& spans)
{
    CV_Assert(bgr.type() == CV_8UC3);
    std::int64_t sum = 0;
    std::int64_t count = 0;
    for (const RowSpan& s : spans) {
        if (s.y < 1 || s.y >= bgr.rows - 1 || (s.y & 3)) continue;
        // Green channel (offset 1) of the rows above, at and below.
        const std::uint8_t* up = bgr.ptr<std::uint8_t>(s.y - 1) + 1;
        const std::uint8_t* mid = bgr.ptr<std::uint8_t>(s.y) + 1;
        const std::uint8_t* down = bgr.ptr<std::uint8_t>(s.y + 1) + 1;
        const int x0 = std::max(1, s.x0);
        const int x1 = std::min(bgr.cols - 1, s.x1);
        for (int x = x0; x < x1; ++x) {
            const int l = 3 * (x - 1);
            const int c = 3 * x;
            const int r = 3 * (x + 1);
            // Kernel [1 -2 1; -2 4 -2; 1 -2 1].
            const int v = up[l] - 2 * up[c] + up[r] - 2 * (mid[l] - 2 * mid[c] + mid[r]) + down[l] - 2 * down[c] + down[r];
            sum += std::abs(v);
        }
        count += std::max(0, x1 - x0);
    }
    if (count == 0) return 0.0;
    // sigma = sqrt(pi / 2) / 6 x mean |kernel response| (the kernel's L2 norm is 6).
    return std::sqrt(M_PI / 2.0) / 6.0 * double(sum) / double(count);
}

}  // namespace omnitune
