#include "calib/config/ProvisionalGeometry.h"

#include "calib/fit/FitText.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

std::string px(double v) { return fixedText(v, 1); }

}  // namespace

ProvisionalGeometry provisionalGeometry(const Config& from, cv::Size frameSize)
{
    ProvisionalGeometry p;
    p.config = from;
    Config& c = p.config;
    GeometryOptions& g = c.geometry;
    // Largest inscribed circle; a pixel inside the border so the rim's dark edge is not in the ring.
    const double outer = std::max(2.0, 0.5 * std::min(frameSize.width, frameSize.height) - 1.0);
    p.scale = outer / from.geometry.outerRadius;
    const double k = p.scale;
    g.imageWidth = frameSize.width;
    g.imageHeight = frameSize.height;
    g.centerX = 0.5 * (frameSize.width - 1);
    g.centerY = 0.5 * (frameSize.height - 1);
    g.outerRadius = outer;
    g.innerRadius = std::min(std::round(from.geometry.innerRadius * k * 100.0) / 100.0, 0.9 * outer);
    p.changes.push_back("geometry: " + std::to_string(frameSize.width) + "x" + std::to_string(frameSize.height) +
                        ", centre (" + px(g.centerX) + ", " + px(g.centerY) + "), outer radius " + px(outer) +
                        " px (the largest circle in the frame), inner radius " + px(g.innerRadius) + " px");
    if (!from.mask.empty() || !from.geometry.maskFile.empty()) {
        p.changes.push_back("mask dropped: " + (from.geometry.maskFile.empty() ? std::string("it") : from.geometry.maskFile) +
                            " was made for " + std::to_string(from.geometry.imageWidth) + "x" +
                            std::to_string(from.geometry.imageHeight) + " frames");
        c.mask.release();
        g.maskFile.clear();
    }
    // Within 2 % the old numbers serve as well as scaled ones, and stay the user's round values.
    if (std::abs(k - 1.0) < 0.02) return p;

    const auto scaled = [k](double v) { return std::round(v * k * 100.0) / 100.0; };  // no 139.4166667 in the panel
    for (double& b : c.hough.areaBounds) b = scaled(b);
    c.hough.nearRobotRadius = scaled(c.hough.nearRobotRadius);
    c.sensors.innerRadius = scaled(c.sensors.innerRadius);
    c.sensors.outerRadius = scaled(c.sensors.outerRadius);
    for (double& r : c.distanceMap.pixelRadii) r = scaled(r);
    // r'(d) = k * r(d / k): the same ball seen by a mirror image k times as large.
    c.ball.c0 *= k;
    c.ball.c2 /= k;
    c.ball.minRadius = std::max(1.0, c.ball.minRadius * k);
    c.ball.maxRadius = std::max(c.ball.minRadius, c.ball.maxRadius * k);
    c.opencvHough.minRadius = std::max(1, int(c.opencvHough.minRadius * k + 0.5));
    c.opencvHough.maxRadius = std::max(c.opencvHough.minRadius, int(c.opencvHough.maxRadius * k + 0.5));
    p.changes.push_back("scaled by " + px(100.0 * k) +
                        " %: radial areas, sensors, distance map radii and the ball model (fit them for this camera)");
    return p;
}

}  // namespace omnitune
