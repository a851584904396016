#include "SpecificHough.h"

#include "BallModel.h"
#include "Geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnitune {

namespace {

// Points of a digital circle of radius r (midpoint algorithm), each once.
std::vector<std::pair<int, int>> circlePoints(int r)
{
    std::vector<std::pair<int, int>> pts;
    if (r <= 0) {
        pts.emplace_back(0, 0);
        return pts;
    }
    int x = r;
    int y = 0;
    int err = 1 - r;
    while (x >= y) {
        const std::pair<int, int> oct[8] = {{x, y}, {y, x}, {-y, x}, {-x, y}, {-x, -y}, {-y, -x}, {y, -x}, {x, -y}};
        for (const auto& p : oct)
            if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
        ++y;
        if (err < 0) {
            err += 2 * y + 1;
        } else {
            --x;
            err += 2 * (y - x) + 1;
        }
    }
    return pts;
}

}  // namespace

SpecificHough::SpecificHough(const SpecificHoughOptions& options, const Geometry& geometry, const BallModel& ball)
    : options_(options), geometry_(&geometry), ball_(&ball)
{
    const auto& b = options.areaBounds;
    if (b.empty() || b.size() > 254) throw std::invalid_argument("hough.area_bounds needs 1..254 bounds");
    for (std::size_t i = 1; i < b.size(); ++i)
        if (!(b[i] > b[i - 1])) throw std::invalid_argument("hough.area_bounds must be strictly increasing");
    if (options.nearRobotWeight < 1 || options.nearRobotWeight > 10)
        throw std::invalid_argument("hough.near_robot_weight must be 1..10");

    circles_.resize(std::size_t(ball.maxRadiusPx()) + 1);
    for (int r = 0; r <= ball.maxRadiusPx(); ++r)
        for (const auto& [dx, dy] : circlePoints(r)) circles_[std::size_t(r)].push_back({dx, dy});

    const cv::Size size = geometry.imageSize();
    weight_.create(size, CV_8UC1);
    areaIndex_.create(size, CV_8UC1);
    radius_.create(size, CV_8UC1);
    for (int y = 0; y < size.height; ++y) {
        for (int x = 0; x < size.width; ++x) {
            const double d = geometry.distanceAt(x, y);
            const bool used = geometry.isUsed(x, y);
            weight_.at<std::uint8_t>(y, x) =
                used ? std::uint8_t(d < options.nearRobotRadius ? options.nearRobotWeight : 1) : 0;
            radius_.at<std::uint8_t>(y, x) = std::uint8_t(ball.radiusIndexAt(d));
            std::uint8_t area = 255;
            if (used) {
                if (!options.multipleMaxima) {
                    area = 0;
                } else {
                    const auto it = std::lower_bound(b.begin(), b.end(), d);
                    if (it != b.end()) area = std::uint8_t(it - b.begin());
                }
            }
            areaIndex_.at<std::uint8_t>(y, x) = area;
        }
    }
    accumulator_ = cv::Mat::zeros(size, CV_16UC1);
    sums_ = cv::Mat::zeros(size, CV_32SC1);
    rowSums_.assign(std::size_t(size.width) * 3, 0);
    best_.resize(options.multipleMaxima ? b.size() : 1);
}

void SpecificHough::process(const cv::Mat& edges, const cv::Mat& binary, std::vector<BallCandidate>& candidates)
{
    const cv::Size size = geometry_->imageSize();
    CV_Assert(edges.type() == CV_8UC1 && edges.size() == size);
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == size);
    const int w = size.width;
    const int h = size.height;

    // Votes: every edge pixel adds its weight on the circle of its expected radius, at centres
    // that are processed and not green (binary 0). weight & ~binary is weight where binary is 0.
    accumulator_.setTo(0);
    for (const RowSpan& s : geometry_->spans()) {
        const std::uint8_t* e = edges.ptr<std::uint8_t>(s.y);
        const std::uint8_t* rad = radius_.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) {
            if (!e[x]) continue;
            for (const Offset& o : circles_[rad[x]]) {
                const int cx = x + o.dx;
                const int cy = s.y + o.dy;
                if (unsigned(cx) >= unsigned(w) || unsigned(cy) >= unsigned(h)) continue;
                const std::uint8_t vote = weight_.ptr<std::uint8_t>(cy)[cx] & std::uint8_t(~binary.ptr<std::uint8_t>(cy)[cx]);
                accumulator_.ptr<std::uint16_t>(cy)[cx] += vote;
            }
        }
    }

    // 3x3 sums: horizontal sums in a 3-row ring, then vertical. Border rows/columns stay 0.
    auto rowSum = [&](int y) -> std::int32_t* {
        std::int32_t* out = rowSums_.data() + std::size_t(y % 3) * std::size_t(w);
        const std::uint16_t* a = accumulator_.ptr<std::uint16_t>(y);
        out[0] = out[w - 1] = 0;
        for (int x = 1; x < w - 1; ++x) out[x] = a[x - 1] + a[x] + a[x + 1];
        return out;
    };
    sums_.row(0).setTo(0);
    sums_.row(h - 1).setTo(0);
    if (h >= 3) {
        rowSum(0);
        rowSum(1);
        for (int y = 1; y < h - 1; ++y) {
            const std::int32_t* down = rowSum(y + 1);
            const std::int32_t* up = rowSums_.data() + std::size_t((y - 1) % 3) * std::size_t(w);
            const std::int32_t* mid = rowSums_.data() + std::size_t(y % 3) * std::size_t(w);
            std::int32_t* out = sums_.ptr<std::int32_t>(y);
            for (int x = 0; x < w; ++x) out[x] = up[x] + mid[x] + down[x];
        }
    }

    // The maximum of the sums in each radial area (or one absolute maximum).
    for (auto& b : best_) b = BallCandidate{};
    for (const RowSpan& s : geometry_->spans()) {
        const std::int32_t* sum = sums_.ptr<std::int32_t>(s.y);
        const std::uint8_t* area = areaIndex_.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) {
            if (area[x] == 255) continue;
            BallCandidate& b = best_[area[x]];
            if (sum[x] > b.accumulator) {
                b.accumulator = sum[x];
                b.x = x;
                b.y = s.y;
            }
        }
    }
    for (std::size_t i = 0; i < best_.size(); ++i) {
        BallCandidate c = best_[i];
        if (c.accumulator < options_.minAccumulator || c.accumulator <= 0) continue;
        c.source = CandidateSource::SpecificHough;
        c.distancePx = geometry_->distanceAt(c.x, c.y);
        const auto& b = options_.areaBounds;
        c.area = int(std::lower_bound(b.begin(), b.end(), c.distancePx) - b.begin());
        c.expectedRadiusPx = ball_->radiusAt(c.distancePx);
        c.radiusPx = c.expectedRadiusPx;
        candidates.push_back(c);
    }
}

}  // namespace omnitune
