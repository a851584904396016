#include "calib/fit/DistanceMapFit.h"

#include "calib/fit/FitText.h"
#include "calib/fit/Polynomial.h"
#include "calib/fit/Residuals.h"
#include "core/DistanceMap.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace omnitune {

namespace {

std::string pointName(const DistancePoint& p)
{
    std::string s = "(" + fixedText(p.radiusPx) + " px, " + fixedText(p.distanceM, 2) + " m";
    if (p.line > 0) s += ", line " + std::to_string(p.line);
    return s + ")";
}

}  // namespace

double DistanceMapFit::distanceAt(double radiusPx) const
{
    if (!pointsTable) return evaluatePolynomial(coefficients, radiusPx);
    DistanceMapOptions table;
    table.pixelRadii = tableRadiiPx;
    table.groundDistances = tableDistancesM;
    return DistanceMap(table).toGround(radiusPx);
}

namespace {

// `suggest`: a fit that bends back names the degrees that do not (each tried without suggesting).
// `anotherRises` (may be null): set when a bent fit found another degree that rises.
DistanceMapFitResult fitAtDegree(const std::vector<DistancePoint>& points, const DistanceMapFitOptions& options, bool suggest,
                                 bool* anotherRises = nullptr)
{
    DistanceMapFitResult result;
    const int degree = options.degree;
    if (degree < 1 || degree > 6) {
        result.error = FitError{FitErrorKind::BadInput, "the distance-map degree must be 1..6, not " + std::to_string(degree)};
        return result;
    }
    if (options.tableSize < 2) {
        result.error = FitError{FitErrorKind::BadInput, "the distance table needs at least 2 radii"};
        return result;
    }
    for (const auto& p : points) {
        if (!(p.radiusPx >= 0) || !(p.distanceM >= 0) || !std::isfinite(p.radiusPx) || !std::isfinite(p.distanceM)) {
            result.error = FitError{FitErrorKind::BadInput, "the point " + pointName(p) +
                                                                " has a negative or non-finite value; fix or remove it"};
            return result;
        }
    }
    std::set<double> radii;
    for (const auto& p : points) radii.insert(p.radiusPx);
    const int needed = degree + 2;
    if (int(points.size()) < needed || int(radii.size()) < degree + 1) {
        result.error = FitError{FitErrorKind::TooFewPoints,
                                "a degree-" + std::to_string(degree) + " distance map needs at least " +
                                    std::to_string(needed) + " points at " + std::to_string(degree + 1) +
                                    " different radii (got " + std::to_string(points.size()) + " at " +
                                    std::to_string(radii.size()) + "); measure more points or lower the degree"};
        return result;
    }

    std::vector<double> x, y;
    for (const auto& p : points) {
        x.push_back(p.radiusPx);
        y.push_back(p.distanceM);
    }
    DistanceMapFit& fit = result.fit;
    fit.coefficients = fitPolynomial(x, y, degree);
    fit.minRadiusPx = *radii.begin();
    fit.maxRadiusPx = *radii.rbegin();

    // Monotone over the span: the slope checked every half pixel (and at both ends); every
    // stretch where it is not positive is named, with the points around it.
    const double span = fit.maxRadiusPx - fit.minRadiusPx;
    const int steps = std::max(200, int(std::ceil(span / 0.5)));
    const auto radiusAt = [&](int i) { return fit.minRadiusPx + span * i / steps; };
    std::string bends, near;
    for (int i = 0; i <= steps; ++i) {
        if (evaluateDerivative(fit.coefficients, radiusAt(i)) > 0) continue;
        int j = i;
        while (j < steps && evaluateDerivative(fit.coefficients, radiusAt(j + 1)) <= 0) ++j;
        const double from = radiusAt(i);
        const double to = radiusAt(j);
        bends += (bends.empty() ? "" : " and ") + fixedText(from) + ".." + fixedText(to) + " px";
        for (const auto& p : points)
            if (p.radiusPx >= from - 0.1 * span && p.radiusPx <= to + 0.1 * span) near += (near.empty() ? "" : ", ") + pointName(p);
        i = j;
    }
    if (!bends.empty()) {
        // Name the degrees that do rise over the span: the user's next try.
        std::string others;
        for (int d = 1; d <= 6 && suggest; ++d) {
            if (d == degree) continue;
            DistanceMapFitOptions o = options;
            o.degree = d;
            const DistanceMapFitResult other = fitAtDegree(points, o, false);
            if (other.ok() && anotherRises) *anotherRises = true;
            if (other.ok())
                others += (others.empty() ? "" : ", ") + std::to_string(d) + " (RMS " + fixedText(other.fit.rmsCm) + " cm)";
        }
        result.error = FitError{FitErrorKind::NotMonotone,
                                "the fitted distance map is not monotone: it bends back at " + bends +
                                    (near.empty() ? "" : " (points there: " + near + ")") +
                                    (others.empty() ? "; check those points, add points around there or lower the degree"
                                                    : "; degree " + others + " rises over all the points: try that, or "
                                                      "check the points there")};
        return result;
    }
    if (fit.distanceAt(fit.minRadiusPx) < 0) {
        result.error = FitError{FitErrorKind::OutOfRange, "the fitted distance map gives " +
                                                              fixedText(fit.distanceAt(fit.minRadiusPx), 2) + " m at " +
                                                              fixedText(fit.minRadiusPx) +
                                                              " px, below zero; check the innermost points or lower the degree"};
        return result;
    }

    for (const auto& p : points) fit.residualsCm.push_back(100.0 * (p.distanceM - fit.distanceAt(p.radiusPx)));
    fit.rmsCm = rootMeanSquare(fit.residualsCm);
    fit.maxAbsCm = maxAbsolute(fit.residualsCm);

    for (int i = 0; i < options.tableSize; ++i) {
        const double r = fit.minRadiusPx + span * i / (options.tableSize - 1);
        fit.tableRadiiPx.push_back(r);
        fit.tableDistancesM.push_back(fit.distanceAt(r));
    }
    DistanceMapOptions table;
    applyDistanceMapFit(fit, table);
    const DistanceMap map(table);  // strictly increasing: the slope is positive over the span
    for (int i = 0; i <= steps; ++i) {
        const double r = fit.minRadiusPx + span * i / steps;
        fit.tableDeviationCm = std::max(fit.tableDeviationCm, 100.0 * std::abs(map.toGround(r) - fit.distanceAt(r)));
    }
    return result;
}

// px: marks out of order in distance by this little in radius are scatter (clicking, the centre a
// pixel or two off in one direction, marks laid 5 cm apart), not a contradiction.
constexpr double kTableScatterPx = 3.0;

}  // namespace

std::optional<DistanceMapFit> fitPointsTable(const std::vector<DistancePoint>& points)
{
    std::map<long, std::pair<double, int>> rings;  // mm -> (radius sum, count)
    for (const DistancePoint& p : points) {
        auto& r = rings[std::lround(p.distanceM * 1000)];
        r.first += p.radiusPx;
        ++r.second;
    }
    struct Pool {
        double distanceSum = 0.0, radiusSum = 0.0;
        int count = 0;
        double radius() const { return radiusSum / count; }
    };
    std::vector<Pool> pools;
    for (const auto& [mm, sum] : rings) {
        const Pool ring{mm / 1000.0 * sum.second, sum.first, sum.second};
        if (!pools.empty() && ring.radius() < pools.back().radius() - kTableScatterPx)
            return std::nullopt;  // a farther mark seen nearer: a mis-typed distance, not the mirror
        pools.push_back(ring);
        while (pools.size() >= 2 && pools.back().radius() <= pools[pools.size() - 2].radius() + 0.05) {
            const Pool last = pools.back();
            pools.pop_back();
            pools.back().distanceSum += last.distanceSum;
            pools.back().radiusSum += last.radiusSum;
            pools.back().count += last.count;
        }
    }
    DistanceMapFit fit;
    fit.pointsTable = true;
    for (const Pool& pool : pools) {
        fit.tableRadiiPx.push_back(pool.radius());
        fit.tableDistancesM.push_back(pool.distanceSum / pool.count);
    }
    if (fit.tableRadiiPx.size() < 3) return std::nullopt;
    fit.minRadiusPx = fit.tableRadiiPx.front();
    fit.maxRadiusPx = fit.tableRadiiPx.back();
    for (const DistancePoint& p : points) fit.residualsCm.push_back(100.0 * (p.distanceM - fit.distanceAt(p.radiusPx)));
    fit.rmsCm = rootMeanSquare(fit.residualsCm);
    fit.maxAbsCm = maxAbsolute(fit.residualsCm);
    return fit;
}

DistanceMapFitResult fitDistanceMap(const std::vector<DistancePoint>& points, const DistanceMapFitOptions& options)
{
    bool anotherRises = false;
    DistanceMapFitResult result = fitAtDegree(points, options, true, &anotherRises);
    // Bent back, and no other degree rises: the points' own table.
    if (result.error && result.error->kind == FitErrorKind::NotMonotone && !anotherRises) {
        if (auto table = fitPointsTable(points)) {
            table->note = "no polynomial of degree 1..6 rises over all the points, so the map is their mean radius per "
                          "measured distance (" + std::to_string(table->tableRadiiPx.size()) + " distances), interpolated "
                          "monotone";
            DistanceMapFitResult r;
            r.fit = std::move(*table);
            return r;
        }
    }
    return result;
}

void applyDistanceMapFit(const DistanceMapFit& fit, DistanceMapOptions& map)
{
    map.pixelRadii = fit.tableRadiiPx;
    map.groundDistances = fit.tableDistancesM;
}

}  // namespace omnitune
