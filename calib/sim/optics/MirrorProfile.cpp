#include "calib/sim/optics/MirrorProfile.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

double HyperbolicMirror::height(double r) const { return a_ * (std::sqrt(1.0 + r * r / (b_ * b_)) - 1.0); }

double HyperbolicMirror::slope(double r) const
{
    return a_ * r / (b_ * b_ * std::sqrt(1.0 + r * r / (b_ * b_)));
}

double HyperbolicMirror::eccentricDistance() const { return std::sqrt(a_ * a_ + b_ * b_); }

double SphericalMirror::height(double r) const { return R_ - std::sqrt(std::max(R_ * R_ - r * r, 0.0)); }

double SphericalMirror::slope(double r) const { return r / std::sqrt(std::max(R_ * R_ - r * r, 1e-12)); }

}  // namespace omnitune
