#include "calib/fit/BallSquashFit.h"

#include "calib/fit/Polynomial.h"

#include <cmath>
#include <vector>

namespace omnitune {

std::optional<std::array<double, 3>> fitBallSquash(const DistanceMapOptions& options, double innerRadius,
                                                   double outerRadius, const BallSquashFitOptions& o)
{
    const DistanceMap map(options);
    const double h = options.viewpointHeight;
    if (!(h > 0) || !(o.stepPx > 0) || !(o.derivativePx > 0)) return std::nullopt;
    auto alphaAt = [&](double rho) { return std::atan2(map.toGround(rho), h); };
    std::vector<double> x, y;
    for (double rho = std::max(innerRadius, o.derivativePx); rho <= outerRadius + 1e-9; rho += o.stepPx) {
        const double slope = (alphaAt(rho + o.derivativePx) - alphaAt(rho - o.derivativePx)) / (2.0 * o.derivativePx);
        if (!(slope > 0)) continue;
        const double k = std::sin(alphaAt(rho)) / (rho * slope);
        if (!(k > 0) || !std::isfinite(k)) continue;
        x.push_back(rho);
        y.push_back(k);
    }
    if (x.size() < 3) return std::nullopt;
    const std::vector<double> c = fitPolynomial(x, y, 2);
    return std::array<double, 3>{c[0], c[1], c[2]};
}

}  // namespace omnitune
