#pragma once
// Image radius (px) -> ground distance (m) from calibration points: a least-squares polynomial
// that must rise over the whole span of the points. A fit that bends back is refused with the
// radius where it does. The config stores the map as a table interpolated by a monotone cubic
// (core/DistanceMap.h), so the fit is written as the polynomial sampled evenly over the points'
// span; `tableDeviationCm` says how far that table strays from the polynomial.
#include "calib/fit/FitError.h"
#include "core/DistanceMap.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct DistancePoint {
    double radiusPx = 0.0;   // image distance from the mirror centre
    double distanceM = 0.0;  // ground distance measured from the robot centre
    int line = 0;            // line in the points file, 0 when not from a file
};

struct DistanceMapFitOptions {
    int degree = 3;      // polynomial degree, 1..6; needs degree + 2 points so the residual means something
    int tableSize = 16;  // radii the config's table gets, evenly from the first to the last point (>= 2)
};

struct DistanceMapFit {
    std::vector<double> coefficients;   // distance(r) = sum c[k] r^k, r in px, distance in m
    double minRadiusPx = 0.0;           // span of the points: the fit holds only here
    double maxRadiusPx = 0.0;
    std::vector<double> residualsCm;    // per point, measured minus fitted
    double rmsCm = 0.0;
    double maxAbsCm = 0.0;
    std::vector<double> tableRadiiPx;   // what goes into distance_map.pixel_radii
    std::vector<double> tableDistancesM;// and distance_map.ground_distances
    double tableDeviationCm = 0.0;      // largest gap between the table's interpolation and the polynomial
    // No polynomial of degree 1..6 rises over all the points (a mirror whose metres per pixel
    // run away near the rim): the table is the points' mean radius per measured distance, as
    // the thesis' distance table, interpolated monotone; `coefficients` is empty then.
    bool pointsTable = false;
    std::string note;                   // how the map was made, when not the asked polynomial

    double distanceAt(double radiusPx) const;
};

struct DistanceMapFitResult {
    DistanceMapFit fit;  // meaningful only when ok()
    std::optional<FitError> error;

    bool ok() const { return !error.has_value(); }
};

// The asked degree; when it bends back, the error names the degrees that do not, and when no
// degree rises over the points the fit is the points' table (`pointsTable`).
DistanceMapFitResult fitDistanceMap(const std::vector<DistancePoint>& points, const DistanceMapFitOptions& options = {});

// The points' own table: their mean radius per measured distance (mm), neighbouring distances
// whose radii do not rise pooled into one (their mean distance at their mean radius), so the
// table rises; `pointsTable` set. None when a farther distance is seen clearly nearer than a
// shorter one (a mis-typed distance) or fewer than 3 distances remain.
std::optional<DistanceMapFit> fitPointsTable(const std::vector<DistancePoint>& points);

// Writes the fit's table into the map (pixel_radii, ground_distances); height and ball radius stay.
void applyDistanceMapFit(const DistanceMapFit& fit, DistanceMapOptions& map);

}  // namespace omnitune
