#include "core/RadialSensors.h"

#include "core/RoundHalfAway.h"

#include <cmath>

namespace omnitune {

RadialSensors::RadialSensors(const RadialSensorOptions& options, const Geometry& geometry) : options_(options)
{
    const auto& g = geometry.options();
    rays_.resize(std::size_t(std::max(options.count, 0)));
    for (int i = 0; i < count(); ++i) {
        const double a = angle(i);
        const double c = std::cos(a);
        const double s = -std::sin(a);  // image y grows downwards
        auto& ray = rays_[std::size_t(i)];
        int lastX = -1;
        int lastY = -1;
        for (double r = options.innerRadius; r <= options.outerRadius; r += 0.5) {
            const int x = roundHalfAway(g.centerX + r * c);
            const int y = roundHalfAway(g.centerY + r * s);
            if (x == lastX && y == lastY) continue;
            lastX = x;
            lastY = y;
            if (x < 0 || y < 0 || x >= g.imageWidth || y >= g.imageHeight || !geometry.isUsed(x, y)) continue;
            ray.push_back({x, y, geometry.distanceAt(x, y)});
        }
    }
}

double radialSensorAngle(const RadialSensorOptions& options, int ray)
{
    return options.angleOffsetDeg * M_PI / 180.0 + 2.0 * M_PI * ray / std::max(options.count, 1);
}

double RadialSensors::angle(int ray) const { return radialSensorAngle(options_, ray); }

void RadialSensors::runs(const cv::Mat& classes, int ray, std::vector<ClassRun>& out) const
{
    CV_Assert(classes.type() == CV_8UC1);
    out.clear();
    const auto& px = rays_[std::size_t(ray)];
    for (int i = 0; i < int(px.size()); ++i) {
        const auto c = static_cast<ColorClass>(classes.at<std::uint8_t>(px[std::size_t(i)].y, px[std::size_t(i)].x));
        if (!out.empty() && out.back().colorClass == c && out.back().last == i - 1) {
            out.back().last = i;
            out.back().endRadius = px[std::size_t(i)].radius;
        } else {
            out.push_back({c, i, i, px[std::size_t(i)].radius, px[std::size_t(i)].radius});
        }
    }
}

}  // namespace omnitune
