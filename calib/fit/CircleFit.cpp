#include "calib/fit/CircleFit.h"

#include "calib/fit/Residuals.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

struct Circle {
    cv::Point2d c;
    double r = 0.0;
};

// Kasa: x^2 + y^2 + D x + E y + F = 0 in least squares; linear, no start value needed.
bool algebraicFit(const std::vector<cv::Point2d>& pts, const std::vector<bool>& use, Circle& out)
{
    int n = 0;
    for (bool u : use) n += u;
    if (n < 3) return false;
    // Centred on the mean for conditioning.
    cv::Point2d mean(0, 0);
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (use[i]) mean += pts[i];
    mean *= 1.0 / n;
    Eigen::MatrixXd a(n, 3);
    Eigen::VectorXd b(n);
    int row = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (!use[i]) continue;
        const double x = pts[i].x - mean.x;
        const double y = pts[i].y - mean.y;
        a(row, 0) = x;
        a(row, 1) = y;
        a(row, 2) = 1.0;
        b(row) = -(x * x + y * y);
        ++row;
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < 3) return false;
    const Eigen::Vector3d s = qr.solve(b);
    const double cx = -0.5 * s(0);
    const double cy = -0.5 * s(1);
    const double r2 = cx * cx + cy * cy - s(2);
    if (!(r2 > 0) || !std::isfinite(r2)) return false;
    out = {{cx + mean.x, cy + mean.y}, std::sqrt(r2)};
    return true;
}

// Minimises sum (|p - c| - r)^2 over the used points, from `c` (a few Gauss-Newton steps).
void geometricRefine(const std::vector<cv::Point2d>& pts, const std::vector<bool>& use, Circle& c)
{
    for (int iteration = 0; iteration < 20; ++iteration) {
        Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
        Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < pts.size(); ++i) {
            if (!use[i]) continue;
            const double dx = pts[i].x - c.c.x;
            const double dy = pts[i].y - c.c.y;
            const double d = std::hypot(dx, dy);
            if (d < 1e-9) continue;
            const Eigen::Vector3d j(-dx / d, -dy / d, -1.0);  // d(residual)/d(cx, cy, r)
            const double res = d - c.r;
            jtj += j * j.transpose();
            jtr += j * res;
        }
        const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
        if (!step.allFinite()) return;
        c.c.x += step(0);
        c.c.y += step(1);
        c.r += step(2);
        if (step.norm() < 1e-6) return;
    }
}

double residual(const cv::Point2d& p, const Circle& c) { return std::hypot(p.x - c.c.x, p.y - c.c.y) - c.r; }

}  // namespace

CircleFit fitCircle(const std::vector<cv::Point2d>& points, const CircleFitOptions& options)
{
    CircleFit fit;
    std::vector<bool> use(points.size(), true);
    Circle c;
    if (!algebraicFit(points, use, c)) return fit;
    for (int round = 0; round < options.rounds; ++round) {
        // Robust spread of the residuals of all points, then keep those within the band.
        std::vector<double> res(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) res[i] = residual(points[i], c);
        const double centreRes = median(res);
        std::vector<double> dev(res.size());
        for (std::size_t i = 0; i < res.size(); ++i) dev[i] = std::abs(res[i] - centreRes);
        const double sigma = 1.4826 * median(dev);
        const double tolerance = std::max(options.outlierSigma * sigma, options.minToleranceP);
        std::vector<bool> next(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) next[i] = std::abs(res[i]) <= tolerance;
        Circle refit;
        if (!algebraicFit(points, next, refit)) break;
        geometricRefine(points, next, refit);
        const bool same = next == use;
        use = next;
        c = refit;
        if (same) break;
    }
    fit.ok = true;
    fit.centre = c.c;
    fit.radius = c.r;
    fit.inlier = use;
    std::vector<double> kept;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (use[i]) kept.push_back(residual(points[i], c));
    fit.inliers = int(kept.size());
    fit.rms = rootMeanSquare(kept);
    return fit;
}

}  // namespace omnitune
