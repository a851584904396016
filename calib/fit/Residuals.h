#pragma once
// Small statistics every fit reports its residuals with.
#include <vector>

namespace omnitune {

// Root mean square of the values (0 for none).
double rootMeanSquare(const std::vector<double>& values);
// Largest absolute value (0 for none).
double maxAbsolute(const std::vector<double>& values);
// Median (0 for none); takes a copy because it reorders.
double median(std::vector<double> values);

}  // namespace omnitune
