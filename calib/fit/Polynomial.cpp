#include "calib/fit/Polynomial.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace omnitune {

std::vector<double> fitPolynomial(const std::vector<double>& x, const std::vector<double>& y, int degree)
{
    assert(x.size() == y.size() && degree >= 0 && !x.empty());
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    const double mid = 0.5 * (*lo + *hi);
    const double half = std::max(0.5 * (*hi - *lo), 1e-12);
    const int n = int(x.size());
    const int m = degree + 1;
    Eigen::MatrixXd a(n, m);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) {
        const double t = (x[std::size_t(i)] - mid) / half;
        double p = 1.0;
        for (int k = 0; k < m; ++k, p *= t) a(i, k) = p;
        b(i) = y[std::size_t(i)];
    }
    const Eigen::VectorXd s = a.colPivHouseholderQr().solve(b);

    // Back to powers of x: t^k = ((x - mid) / half)^k, expanded binomially.
    std::vector<double> c(std::size_t(m), 0.0);
    for (int k = 0; k < m; ++k) {
        const double scale = s(k) / std::pow(half, k);
        double binom = 1.0;  // C(k, j)
        for (int j = 0; j <= k; ++j) {
            c[std::size_t(j)] += scale * binom * std::pow(-mid, k - j);
            binom = binom * (k - j) / (j + 1);
        }
    }
    return c;
}

double evaluatePolynomial(const std::vector<double>& coefficients, double x)
{
    double v = 0.0;
    for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it) v = v * x + *it;
    return v;
}

double evaluateDerivative(const std::vector<double>& coefficients, double x)
{
    double v = 0.0;
    for (std::size_t k = coefficients.size(); k-- > 1;) v = v * x + double(k) * coefficients[k];
    return v;
}

}  // namespace omnitune
