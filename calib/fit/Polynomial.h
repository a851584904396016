#pragma once
// Least-squares polynomials, shared by the distance-map and ball-model fits. Coefficients are
// in ascending powers of x in the caller's units (c[0] + c[1]*x + c[2]*x^2 ...), the form the
// config stores; the fit itself runs on x shifted and scaled to [-1, 1] so that radii of a few
// hundred pixels raised to the 5th power do not ruin the conditioning.
#include <vector>

namespace omnitune {

// Least-squares coefficients of the given degree through (x[i], y[i]). The caller checks that
// there are more distinct x than the degree; `x` and `y` have the same size.
std::vector<double> fitPolynomial(const std::vector<double>& x, const std::vector<double>& y, int degree);

double evaluatePolynomial(const std::vector<double>& coefficients, double x);
// d/dx of the polynomial at x.
double evaluateDerivative(const std::vector<double>& coefficients, double x);

}  // namespace omnitune
