#include "calib/session/TruthMarkRules.h"

#include "core/BallModel.h"
#include "core/BallPosition.h"

#include <cmath>
#include <cstdio>

namespace omnitune {

namespace {
std::string px(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}
}  // namespace

std::optional<std::string> radiusFarFromModel(double radiusPx, const BallModelOptions& ball)
{
    if (radiusPx <= ball.maxRadius * kMarkRadiusFarFactor && radiusPx >= ball.minRadius / kMarkRadiusFarFactor)
        return std::nullopt;
    return "a radius of " + px(radiusPx) + " px is far outside the ball model's " + px(ball.minRadius) + " to " +
           px(ball.maxRadius) + " px (ball.min_radius, ball.max_radius)";
}

std::optional<std::string> makeBallMark(const Config& config, cv::Size imageSize, int frame, double x, double y,
                                        double radiusPx, TruthRow& out)
{
    if (x < 0 || y < 0 || x >= imageSize.width || y >= imageSize.height)
        return std::string("the ball's centre must lie inside the image");
    const GeometryOptions& g = config.geometry;
    if (radiusPx <= 0) radiusPx = BallModel(config.ball).radiusAt(std::hypot(x - g.centerX, y - g.centerY));
    TruthRow row;
    row.frame = frame;
    row.ballVisible = true;
    row.px = x;
    row.py = y;
    row.radiusPx = radiusPx;
    try {
        const BallPosition at = ballPositionAt(x, y, g.centerX, g.centerY, DistanceMap(config.distanceMap));
        row.xM = at.xM;
        row.yM = at.yM;
    } catch (const std::exception& e) {
        return std::string("the config's distance map is not usable: ") + e.what();
    }
    out = row;
    return std::nullopt;
}

TruthRow detectionMark(int frame, const BallDetection& d)
{
    TruthRow row;
    row.frame = frame;
    row.ballVisible = d.found;
    if (!d.found) return row;
    row.px = d.px;
    row.py = d.py;
    row.radiusPx = d.radiusPx;
    row.xM = d.xM;
    row.yM = d.yM;
    return row;
}

}  // namespace omnitune
