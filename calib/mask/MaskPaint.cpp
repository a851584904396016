#include "calib/mask/MaskPaint.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

double segmentDistanceSquared(cv::Point2d p, cv::Point2d a, cv::Point2d b)
{
    const cv::Point2d ab = b - a;
    const double len2 = ab.dot(ab);
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const cv::Point2d d = p - (a + t * ab);
    return d.dot(d);
}

}  // namespace

int paintStroke(cv::Mat& mask, cv::Point2d a, cv::Point2d b, double radius, std::uint8_t value)
{
    CV_Assert(mask.type() == CV_8UC1);
    if (!(radius >= 0.0)) return 0;
    // Only the box around the stroke can change; centres are at +0.5.
    const int x0 = std::max(0, int(std::floor(std::min(a.x, b.x) - radius - 0.5)));
    const int y0 = std::max(0, int(std::floor(std::min(a.y, b.y) - radius - 0.5)));
    const int x1 = std::min(mask.cols - 1, int(std::ceil(std::max(a.x, b.x) + radius)));
    const int y1 = std::min(mask.rows - 1, int(std::ceil(std::max(a.y, b.y) + radius)));
    const double r2 = radius * radius;
    int changed = 0;
    for (int y = y0; y <= y1; ++y) {
        auto* row = mask.ptr<std::uint8_t>(y);
        for (int x = x0; x <= x1; ++x) {
            if (row[x] == value || segmentDistanceSquared({x + 0.5, y + 0.5}, a, b) > r2) continue;
            row[x] = value;
            ++changed;
        }
    }
    return changed;
}

int fillPolygon(cv::Mat& mask, const std::vector<cv::Point2d>& vertices, std::uint8_t value)
{
    CV_Assert(mask.type() == CV_8UC1);
    if (vertices.size() < 3) return 0;
    int changed = 0;
    std::vector<double> crossings;
    for (int y = 0; y < mask.rows; ++y) {
        // Where the row of pixel centres crosses the outline; each edge counts its lower end
        // and not its upper one, so a vertex on the row is crossed once, not twice.
        const double cy = y + 0.5;
        crossings.clear();
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const cv::Point2d& p = vertices[i];
            const cv::Point2d& q = vertices[(i + 1) % vertices.size()];
            if ((p.y <= cy) == (q.y <= cy)) continue;
            crossings.push_back(p.x + (cy - p.y) * (q.x - p.x) / (q.y - p.y));
        }
        std::sort(crossings.begin(), crossings.end());
        auto* row = mask.ptr<std::uint8_t>(y);
        for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
            // Centres x + 0.5 in [left, right): x from ceil(left - 0.5) to ceil(right - 0.5) - 1.
            const int from = std::max(0, int(std::ceil(crossings[i] - 0.5)));
            const int to = std::min(mask.cols, int(std::ceil(crossings[i + 1] - 0.5)));
            for (int x = from; x < to; ++x) {
                if (row[x] == value) continue;
                row[x] = value;
                ++changed;
            }
        }
    }
    return changed;
}

int floodFillMask(cv::Mat& mask, cv::Point2d seed, std::uint8_t value)
{
    CV_Assert(mask.type() == CV_8UC1);
    const cv::Point at(int(std::floor(seed.x)), int(std::floor(seed.y)));
    if (at.x < 0 || at.y < 0 || at.x >= mask.cols || at.y >= mask.rows) return 0;
    if (mask.at<std::uint8_t>(at) == value) return 0;
    // Exact equality (zero tolerance): the region is the seed's value, nothing near it.
    return cv::floodFill(mask, at, cv::Scalar(value), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
}

}  // namespace omnitune
