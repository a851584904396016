#include "calib/fit/Residuals.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

double rootMeanSquare(const std::vector<double>& values)
{
    if (values.empty()) return 0.0;
    double sum = 0.0;
    for (const double v : values) sum += v * v;
    return std::sqrt(sum / double(values.size()));
}

double maxAbsolute(const std::vector<double>& values)
{
    double m = 0.0;
    for (const double v : values) m = std::max(m, std::abs(v));
    return m;
}

double median(std::vector<double> values)
{
    if (values.empty()) return 0.0;
    const auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

}  // namespace omnitune
