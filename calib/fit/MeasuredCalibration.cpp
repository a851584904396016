#include "calib/fit/MeasuredCalibration.h"

#include "calib/fit/BallSquashFit.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace omnitune {

namespace {

// Inner radius from the mask: the largest radius of the masked blob around the centre.
std::optional<double> maskBodyRadius(const cv::Mat& mask, cv::Point2d centre, double outer)
{
    if (mask.empty()) return std::nullopt;
    // Walk rays out from the centre until the first processed pixel; the median over the rays
    // ignores rods that start at the body.
    std::vector<double> radii;
    for (int k = 0; k < 180; ++k) {
        const double a = 2 * CV_PI * k / 180;
        for (double r = 0; r < outer; r += 0.5) {
            const int x = int(std::lround(centre.x + r * std::cos(a))), y = int(std::lround(centre.y + r * std::sin(a)));
            if (x < 0 || y < 0 || x >= mask.cols || y >= mask.rows) break;
            if (mask.at<uchar>(y, x)) {
                radii.push_back(r);
                break;
            }
        }
    }
    if (radii.size() < 90) return std::nullopt;
    std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
    return radii[radii.size() / 2];
}

}  // namespace

MeasuredCalibration calibrateFromMeasurements(const Config& base, const CameraMeasurements& m,
                                              const MeasuredCalibrationOptions& options)
{
    MeasuredCalibration out;
    Config c = base;
    if (m.emptyFrames.empty()) {
        out.error = "no empty-field frames for the rim fit";
        return out;
    }
    const cv::Size size = m.emptyFrames.front().size();

    // Rim: centre and outer radius.
    RimFitOptions rimOptions;
    rimOptions.marginPx = options.rimMarginPx;
    const RimFitResult rim = fitRim(m.emptyFrames, rimOptions);
    if (!rim.ok()) {
        out.error = "rim fit: " + rim.error->toString();
        return out;
    }
    out.rim = rim.fit;
    applyRimFit(rim.fit, size, c.geometry);
    const cv::Point2d centre = rim.fit.centre;

    // Body: inner radius.
    BodyFitOptions bodyOptions;
    bodyOptions.marginPx = options.bodyMarginPx;
    const BodyFitResult body = fitBody(m.emptyFrames, centre, rim.fit.rimRadius, bodyOptions);
    if (body.ok()) {
        out.body = body.fit;
        c.geometry.innerRadius = body.fit.innerRadius;
    } else if (auto r = maskBodyRadius(m.mask, centre, c.geometry.outerRadius)) {
        c.geometry.innerRadius = *r + options.bodyMarginPx;
    } else {
        out.error = "body fit: " + body.error->toString() + "; and no mask to read the body from";
        return out;
    }
    if (c.geometry.innerRadius >= c.geometry.outerRadius - 10) {
        out.error = "the fitted inner radius leaves no ring";
        return out;
    }

    // Distance map. Near the rim of a mirror the ground distance runs away (metres per pixel),
    // which no low polynomial in the radius follows; so the marks' mean radius per distance
    // (the least-squares radius of each ring of marks) is the table too, as in the thesis'
    // distance table, and whichever reproduces the marks better is kept.
    const std::vector<DistancePoint> points = toDistancePoints(m.points, centre);
    std::optional<DistanceMapFit> best;
    for (int degree = 3; degree <= 6; ++degree) {
        DistanceMapFitOptions o;
        o.degree = degree;
        o.tableSize = options.tableSize;
        const DistanceMapFitResult fit = fitDistanceMap(points, o);
        // Polynomials only: the marks' own table is weighed below (ringMap).
        if (fit.ok() && !fit.fit.pointsTable && (!best || fit.fit.rmsCm < best->rmsCm * 0.9)) {
            best = fit.fit;
            out.distanceMapDegree = degree;
        }
    }
    DistanceMapOptions polyMap = c.distanceMap, ringMap = c.distanceMap;
    if (best) applyDistanceMapFit(*best, polyMap);
    ringMap.pixelRadii.clear();
    ringMap.groundDistances.clear();
    if (const auto rings = fitPointsTable(points)) applyDistanceMapFit(*rings, ringMap);
    auto withOrigin = [](DistanceMapOptions map) {
        // Below the first mark the map runs straight to (0 px, 0 m): put that point in the table.
        if (!map.pixelRadii.empty() && map.pixelRadii.front() > 1) {
            map.pixelRadii.insert(map.pixelRadii.begin(), 0.0);
            map.groundDistances.insert(map.groundDistances.begin(), 0.0);
        }
        return map;
    };
    auto marksRmsCm = [&](const DistanceMapOptions& map) {
        if (map.pixelRadii.size() < 3) return 1e9;
        const DistanceMap dm(map);
        double sum = 0;
        for (const DistancePoint& p : points) sum += std::pow(100 * (dm.toGround(p.radiusPx) - p.distanceM), 2);
        return std::sqrt(sum / std::max<std::size_t>(points.size(), 1));
    };
    polyMap = withOrigin(polyMap);
    ringMap = withOrigin(ringMap);
    const double polyRms = best ? marksRmsCm(polyMap) : 1e9, ringRms = marksRmsCm(ringMap);
    if (!best && ringMap.pixelRadii.size() < 4) {
        out.error = "distance map: too few marks";
        return out;
    }
    if (best) out.distanceMap = *best;
    out.distanceMapFromRings = ringRms < polyRms;
    out.distanceMapRmsCm = std::min(ringRms, polyRms);
    c.distanceMap = out.distanceMapFromRings ? ringMap : polyMap;
    if (m.viewpointHeight > 0) c.distanceMap.viewpointHeight = m.viewpointHeight;

    // Ball model from the located circles.
    out.ballSamples.clear();
    double minR = 1e9, maxR = 0;
    for (const BallMark& b : m.balls) {
        out.ballSamples.push_back({std::hypot(b.x - centre.x, b.y - centre.y), b.radiusPx, -1, std::atan2(b.y - centre.y, b.x - centre.x)});
        minR = std::min(minR, b.radiusPx);
        maxR = std::max(maxR, b.radiusPx);
    }
    const BallModelFitResult ball = fitBallModel(out.ballSamples);
    if (!ball.ok()) {
        out.error = "ball model: " + ball.error->toString();
        return out;
    }
    out.ballModel = ball.fit;
    applyBallModelFit(ball.fit, c.ball);
    c.ball.maxRadius = std::min(maxR + options.maxRadiusMarginPx, 200.0);
    c.ball.minRadius = std::clamp(minR - options.minRadiusMarginPx, 2.0, c.ball.maxRadius - 1);
    c.opencvHough.minRadius = std::max(1, int(std::floor(c.ball.minRadius)));
    c.opencvHough.maxRadius = std::max(c.opencvHough.minRadius + 1, int(std::ceil(c.ball.maxRadius)));
    // The ball's ellipse from the distance map (the optics that squash the ground squash the ball).
    if (const auto k = fitBallSquash(c.distanceMap, c.geometry.innerRadius, c.geometry.outerRadius)) {
        c.ball.squashC0 = (*k)[0];
        c.ball.squashC1 = (*k)[1];
        c.ball.squashC2 = (*k)[2];
    }

    // The Hough's radial areas and near-robot radius, from the default ring onto the fitted one.
    const GeometryOptions defaults;
    const double inner0 = defaults.innerRadius, outer0 = defaults.outerRadius;
    const double inner = c.geometry.innerRadius, outer = c.geometry.outerRadius;
    // To 0.1 px: a tenth is far below what a radial area's edge means, and the panel stays readable.
    auto rescale = [&](double v) {
        return std::round(10.0 * (inner + (v - inner0) * (outer - inner) / (outer0 - inner0))) / 10.0;
    };
    for (double& b : c.hough.areaBounds) b = rescale(b);
    if (!c.hough.areaBounds.empty()) c.hough.areaBounds.back() = outer;
    c.hough.nearRobotRadius = std::max(0.0, rescale(c.hough.nearRobotRadius));
    c.sensors.innerRadius = inner;
    c.sensors.outerRadius = outer;

    c.mask = m.mask.empty() ? cv::Mat() : m.mask.clone();
    c.geometry.maskFile = m.mask.empty() ? std::string() : std::string("mask.png");
    out.config = c;
    return out;
}

std::string ballSamplesCsv(const std::vector<BallSample>& samples)
{
    std::string text = "distance_px,radius_px\n";
    char buf[80];
    for (const BallSample& s : samples) {
        std::snprintf(buf, sizeof buf, "%.3f,%.3f\n", s.distancePx, s.radiusPx);
        text += buf;
    }
    return text;
}

}  // namespace omnitune
