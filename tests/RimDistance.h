#pragma once
// The distance at which a ball reaches a given way past the mirror's rim, for the rim tests.
#include "DrawnScene.h"

namespace omnitune::test {

// A distance whose ball circle reaches `overhang` px past outer_radius - rim_margin_px (the
// expected radius grows with the distance, so a few fixed-point steps).
inline double distanceOverhanging(const Config& c, double overhang)
{
    double d = c.geometry.outerRadius;
    for (int i = 0; i < 20; ++i)
        d = c.geometry.outerRadius - c.validation.rimMarginPx + overhang - expectedRadius(c, d);
    return d;
}

}  // namespace omnitune::test
