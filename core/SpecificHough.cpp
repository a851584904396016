#include "core/SpecificHough.h"

#include "core/BallModel.h"
#include "core/FillBytes.h"
#include "core/Geometry.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace omnitune {

SpecificHough::SpecificHough(const SpecificHoughOptions& options, const Geometry& geometry, const BallModel& ball)
    : options_(options), geometry_(&geometry), ball_(&ball)
{
    // User values are checked once, by checkConfig(); this guards the area index image (one
    // byte per pixel, 255 = none) against a caller that skipped it.
    const auto& b = options.areaBounds;
    CV_Assert(!b.empty() && b.size() < 255);

    // For each edge distance d, the centres a ball edge there may belong to: in direction phi
    // from the ray, at the radius r solving r = R(d + r cos phi), about one point per pixel of
    // arc. A few fixed-point steps converge: |dR/dd| is far below 1 for any sane ball model.
    const int maxEdgeDistance = int(std::ceil(geometry.options().outerRadius)) + 1;
    loci_.resize(std::size_t(maxEdgeDistance) + 1);
    for (int d = 0; d <= maxEdgeDistance; ++d) {
        const double r0 = ball.radiusAt(d);
        const int n = std::max(8, int(std::ceil(2.0 * M_PI * r0)));
        auto& locus = loci_[std::size_t(d)];
        for (int k = 0; k < n; ++k) {
            const double phi = 2.0 * M_PI * k / n;
            double r = r0;
            for (int it = 0; it < 6 && options.radiusAtCentre; ++it)
                r = ball.radiusAt(std::max(0.0, d + r * std::cos(phi)));
            locus.push_back({float(r * std::cos(phi)), float(r * std::sin(phi))});
        }
    }

    const cv::Size size = geometry.imageSize();
    weight_.create(size, CV_8UC1);
    areaIndex_.create(size, CV_8UC1);
    for (int y = 0; y < size.height; ++y) {
        for (int x = 0; x < size.width; ++x) {
            const double d = geometry.distanceAt(x, y);
            const bool used = geometry.isUsed(x, y);
            weight_.at<std::uint8_t>(y, x) =
                used ? std::uint8_t(d < options.nearRobotRadius ? options.nearRobotWeight : 1) : 0;
            std::uint8_t area = 255;
            if (used) {
                area = std::uint8_t(options.multipleMaxima ? areaOf(d) : 0);
            }
            areaIndex_.at<std::uint8_t>(y, x) = area;
        }
    }
    accumulator_ = cv::Mat::zeros(size, CV_16UC1);
    sums_ = cv::Mat::zeros(size, CV_32SC1);
    rowSums_.assign(std::size_t(size.width) * 3, 0);
    best_.resize(options.multipleMaxima ? b.size() : 1);
}

int SpecificHough::areaOf(double distance) const
{
    const auto& b = options_.areaBounds;
    const auto it = std::lower_bound(b.begin(), b.end(), distance);
    return int(std::min<std::size_t>(std::size_t(it - b.begin()), b.size() - 1));
}

void SpecificHough::process(const cv::Mat& edges, const cv::Mat& binary, std::vector<BallCandidate>& candidates)
{
    const cv::Size size = geometry_->imageSize();
    CV_Assert(edges.type() == CV_8UC1 && edges.size() == size);
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == size);
    const int w = size.width;
    const int h = size.height;

    // Votes: every edge pixel adds its weight on its locus, at centres that are processed and
    // not green (binary 0): weight & ~binary is the weight where binary is 0, else 0.
    const double cx0 = geometry_->options().centerX;
    const double cy0 = geometry_->options().centerY;
    fillBytes(accumulator_, 0);
    for (const RowSpan& s : geometry_->spans()) {
        const std::uint8_t* e = edges.ptr<std::uint8_t>(s.y);
        const float* dist = geometry_->distance().ptr<float>(s.y);
        for (int x = s.x0; x < s.x1; ++x) {
            if (!e[x] || dist[x] < 0.5f) continue;
            const float nx = float((x - cx0) / dist[x]);  // unit ray from the robot centre
            const float ny = float((s.y - cy0) / dist[x]);
            const auto& locus = loci_[std::min(std::size_t(cvRound(dist[x])), loci_.size() - 1)];
            int lastDx = INT_MIN;
            int lastDy = INT_MIN;
            for (const LocusPoint& p : locus) {
                const int dx = cvRound(p.along * nx - p.across * ny);
                const int dy = cvRound(p.along * ny + p.across * nx);
                if (dx == lastDx && dy == lastDy) continue;  // neighbouring samples, same pixel
                lastDx = dx;
                lastDy = dy;
                const int cx = x + dx;
                const int cy = s.y + dy;
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
    cv::Mat top = sums_.row(0);
    cv::Mat bottom = sums_.row(h - 1);
    fillBytes(top, 0);
    fillBytes(bottom, 0);
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
        c.area = areaOf(c.distancePx);
        c.expectedRadiusPx = ball_->radiusAt(c.distancePx);
        c.radiusPx = c.expectedRadiusPx;
        candidates.push_back(c);
    }
}

}  // namespace omnitune
