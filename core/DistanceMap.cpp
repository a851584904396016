#include "core/DistanceMap.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>

namespace omnitune {

DistanceMap::DistanceMap(const DistanceMapOptions& options) : options_(options)
{
    const auto& x = options.pixelRadii;
    const auto& y = options.groundDistances;
    // User values (increasing points, viewpoint above the ball) are checked once, by
    // checkConfig(); this guards the tables below against a caller that skipped it.
    CV_Assert(x.size() >= 2 && x.size() == y.size());

    // Fritsch-Carlson tangents: monotone data gives a monotone interpolant.
    const std::size_t n = x.size();
    std::vector<double> secant(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) secant[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
    slopes_.assign(n, 0.0);
    slopes_[0] = secant[0];
    slopes_[n - 1] = secant[n - 2];
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double a = secant[i - 1];
        const double b = secant[i];
        if (a * b <= 0) continue;
        const double w1 = 2 * (x[i + 1] - x[i]) + (x[i] - x[i - 1]);
        const double w2 = (x[i + 1] - x[i]) + 2 * (x[i] - x[i - 1]);
        slopes_[i] = (w1 + w2) / (w1 / a + w2 / b);  // weighted harmonic mean
    }
}

double DistanceMap::toGround(double px) const
{
    const auto& x = options_.pixelRadii;
    const auto& y = options_.groundDistances;
    // Before the first point: straight down towards (0 px, 0 m), never a negative distance.
    if (px <= x.front()) return x.front() > 0 ? y.front() * std::max(px, 0.0) / x.front() : y.front();
    if (px >= x.back()) return y.back() + (px - x.back()) * slopes_.back();
    const std::size_t i = std::size_t(std::upper_bound(x.begin(), x.end(), px) - x.begin()) - 1;
    const double h = x[i + 1] - x[i];
    const double t = (px - x[i]) / h;
    const double t2 = t * t;
    const double t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y[i] + (t3 - 2 * t2 + t) * h * slopes_[i] + (-2 * t3 + 3 * t2) * y[i + 1] +
           (t3 - t2) * h * slopes_[i + 1];
}

double DistanceMap::toPixels(double metres) const
{
    const auto& x = options_.pixelRadii;
    const auto& y = options_.groundDistances;
    if (metres <= y.front()) return y.front() > 0 ? x.front() * std::max(metres, 0.0) / y.front() : x.front();
    if (metres >= y.back()) return x.back() + (metres - y.back()) / slopes_.back();
    double lo = x.front();
    double hi = x.back();
    for (int i = 0; i < 60 && hi - lo > 1e-9; ++i) {  // toGround is monotone: bisect
        const double mid = 0.5 * (lo + hi);
        (toGround(mid) < metres ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double DistanceMap::ballDistance(double px) const
{
    const double h = options_.viewpointHeight;
    return toGround(px) * (h - options_.ballRadius) / h;
}

double DistanceMap::ballPixels(double metres) const
{
    const double h = options_.viewpointHeight;
    return toPixels(metres * h / (h - options_.ballRadius));
}

}  // namespace omnitune
