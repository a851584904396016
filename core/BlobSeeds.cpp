#include "core/BlobSeeds.h"

#include "core/BallEllipse.h"
#include "core/BallModel.h"
#include "core/FillBytes.h"
#include "core/Geometry.h"
#include "core/ExpectedRadius.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

BlobSeeds::Region BlobSeeds::flood(const cv::Mat& binary, int start)
{
    // Breadth-first over a queue that holds every pixel of the region once: queue_ has room for
    // the whole image, so it never grows.
    const int w = binary.cols;
    const int h = binary.rows;
    std::uint8_t* seen = seen_.ptr<std::uint8_t>(0);
    const std::uint8_t* bin = binary.ptr<std::uint8_t>(0);
    Region r;
    r.x0 = r.x1 = start % w;
    r.y0 = r.y1 = start / w;
    double sx = 0;
    double sy = 0;
    std::size_t head = 0;
    std::size_t tail = 0;
    queue_[tail++] = start;
    seen[start] = 1;
    while (head < tail) {
        const int p = queue_[head++];
        const int x = p % w;
        const int y = p / w;
        ++r.area;
        sx += x;
        sy += y;
        r.x0 = std::min(r.x0, x);
        r.x1 = std::max(r.x1, x);
        r.y0 = std::min(r.y0, y);
        r.y1 = std::max(r.y1, y);
        for (int dy = -1; dy <= 1; ++dy) {
            const int ny = y + dy;
            if (ny < 0 || ny >= h) continue;
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = x + dx;
                if (nx < 0 || nx >= w) continue;
                const int q = ny * w + nx;
                if (seen[q] || bin[q] == 255) continue;
                seen[q] = 1;
                queue_[tail++] = q;
            }
        }
    }
    r.cx = sx / r.area;
    r.cy = sy / r.area;
    return r;
}

void BlobSeeds::keep(const BlobSeed& seed, int maxSeeds)
{
    if (int(seeds_.size()) >= maxSeeds && !(seed.fit < seeds_.back().fit)) return;
    auto at = std::upper_bound(seeds_.begin(), seeds_.end(), seed.fit,
                               [](double fit, const BlobSeed& s) { return fit < s.fit; });
    if (int(seeds_.size()) >= maxSeeds) seeds_.pop_back();  // `at` stays valid: it is not past the end
    seeds_.insert(at, seed);
}

const std::vector<BlobSeed>& BlobSeeds::find(const cv::Mat& binary, const Geometry& geometry, const BallModel& ball,
                                             int maxSeeds, bool squashed)
{
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == geometry.imageSize() && binary.isContinuous());
    maxSeeds = std::max(0, maxSeeds);
    seeds_.clear();
    if (seeds_.capacity() < std::size_t(maxSeeds) + 1) seeds_.reserve(std::size_t(maxSeeds) + 1);
    if (maxSeeds == 0) return seeds_;
    seen_.create(binary.size(), CV_8UC1);
    fillBytes(seen_, 0);
    queue_.resize(binary.total());
    // Only processed pixels start a region (unprocessed ones are 255 in `binary` anyway).
    for (const RowSpan& s : geometry.spans()) {
        const std::uint8_t* bin = binary.ptr<std::uint8_t>(s.y);
        const std::uint8_t* seen = seen_.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) {
            if (bin[x] == 255 || seen[x]) continue;
            const Region r = flood(binary, s.y * binary.cols + x);
            if (r.area < 4) continue;  // pixel speckle, never a ball we could validate
            const int cx = int(std::lround(r.cx));
            const int cy = int(std::lround(r.cy));
            if (!geometry.isUsed(cx, cy)) continue;
            const double radius = expectedRadiusAt(geometry, ball, cx, cy);
            const double ratio = r.area / (M_PI * radius * radius);
            if (ratio < kMinAreaRatio || ratio > kMaxAreaRatio) continue;
            // Compact: no side longer than the ball (plus a pixel of blur either side); squashed,
            // its longer (tangential) axis.
            const double squash = squashed ? ball.squashAt(geometry.distanceAt(cx, cy)) : 1.0;
            const double side = 2.0 * squashedTangentialRadius(radius, std::min(1.0, squash)) + 2.0;
            if (r.x1 - r.x0 + 1 > side || r.y1 - r.y0 + 1 > side) continue;
            keep(BlobSeed{cx, cy, std::abs(std::log(ratio))}, maxSeeds);
        }
    }
    return seeds_;
}

}  // namespace omnitune
