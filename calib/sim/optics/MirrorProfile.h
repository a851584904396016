#pragma once
// The mirror of an omnidirectional camera as a surface of revolution about its vertical axis:
// height h(r) above the mirror's lowest point (its vertex) at horizontal distance r from the
// axis, and the slope dh/dr, up to the rim. The camera looks up at it from below.
#include <memory>
#include <string>

namespace omnitune {

class MirrorProfile {
public:
    virtual ~MirrorProfile() = default;
    virtual double height(double r) const = 0;  // m above the vertex
    virtual double slope(double r) const = 0;   // dh/dr
    virtual double rimRadius() const = 0;       // m; the mirror ends here
    virtual std::string name() const = 0;
};

// One sheet of a hyperboloid (z/a)^2 - (r/b)^2 = 1 (vertex at z = a). With the camera's pinhole
// at the other sheet's focus, 2 sqrt(a^2 + b^2) below the mirror's own focus, every reflected
// ray passes through that focus: a single effective viewpoint sqrt(a^2+b^2) - a above the vertex.
class HyperbolicMirror final : public MirrorProfile {
public:
    HyperbolicMirror(double a, double b, double rim) : a_(a), b_(b), rim_(rim) {}
    double height(double r) const override;
    double slope(double r) const override;
    double rimRadius() const override { return rim_; }
    std::string name() const override { return "hyperbolic"; }
    double eccentricDistance() const;  // sqrt(a^2 + b^2): centre to focus
    double a() const { return a_; }

private:
    double a_, b_, rim_;
};

// A spherical cap of radius R: cheap to make, no single viewpoint (the reflected rays cross
// the axis at slightly different heights), a far field compressed towards the rim.
class SphericalMirror final : public MirrorProfile {
public:
    SphericalMirror(double sphereRadius, double rim) : R_(sphereRadius), rim_(rim) {}
    double height(double r) const override;
    double slope(double r) const override;
    double rimRadius() const override { return rim_; }
    std::string name() const override { return "spherical"; }

private:
    double R_, rim_;
};

}  // namespace omnitune
