#include "calib/sim/optics/OpticsRenderer.h"

#include "core/Pi.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <tuple>
#include <utility>
#include <vector>

namespace omnitune {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kLineStep = 0.02;    // m, line-distance grid
constexpr double kCarpetStep = 0.10;  // m, carpet-shade grid
constexpr int kNoiseMargin = 97;      // px of extra noise table: offsets a seed can pick per axis

// Colours (BGR) at normal light.
const cv::Vec3f kLine(232, 234, 232);
const cv::Vec3f kHallFloor(96, 106, 110);
const cv::Vec3f kWall(128, 124, 118);
const cv::Vec3f kHousing(9, 9, 10);
const cv::Vec3f kRod(52, 52, 58);
const cv::Vec3f kMast(12, 12, 14);
const cv::Vec3f kPlate(50, 50, 54);
const cv::Vec3f kPlateDark(30, 30, 33);
const cv::Vec3f kRobotBlack(24, 24, 26);
const cv::Vec3f kRobotTop(36, 36, 38);
const cv::Vec3f kCyan(200, 185, 25);
const cv::Vec3f kMagenta(190, 35, 200);
const cv::Vec3f kShoe(36, 36, 40);
const cv::Vec3f kJeans(112, 72, 48);
const cv::Vec3d kLightDir = cv::normalize(cv::Vec3d(0.25, 0.15, 1.0));  // overhead hall light

double smoothstep(double e0, double e1, double x)
{
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

float bilinear(const cv::Mat& grid, double gx, double gy)
{
    const int x0 = std::clamp(int(std::floor(gx)), 0, grid.cols - 2);
    const int y0 = std::clamp(int(std::floor(gy)), 0, grid.rows - 2);
    const float fx = float(std::clamp(gx - x0, 0.0, 1.0)), fy = float(std::clamp(gy - y0, 0.0, 1.0));
    const float* r0 = grid.ptr<float>(y0);
    const float* r1 = grid.ptr<float>(y0 + 1);
    return (r0[x0] * (1 - fx) + r0[x0 + 1] * fx) * (1 - fy) + (r1[x0] * (1 - fx) + r1[x0 + 1] * fx) * fy;
}

bool azimuthInside(float az, float centre, float halfWidth)
{
    float d = az - centre;
    while (d > float(kPi)) d -= float(2 * kPi);
    while (d < -float(kPi)) d += float(2 * kPi);
    return std::abs(d) <= halfWidth;
}

// Distance to the nearest line centre every kLineStep m over the carpet. Shared by every renderer
// of the same field (the cells of a run use one), as it takes a good part of a second.
cv::Mat lineDistanceGrid(const FieldModel& field)
{
    static std::mutex mutex;
    static std::vector<std::pair<FieldDimensions, cv::Mat>> cache;
    const FieldDimensions& d = field.dimensions();
    const auto same = [](const FieldDimensions& a, const FieldDimensions& b) {
        return std::tie(a.length, a.width, a.lineWidth, a.centerCircleRadius, a.goalAreaDepth, a.goalAreaWidth,
                        a.penaltyAreaDepth, a.penaltyAreaWidth, a.cornerArcRadius, a.penaltyMarkDistance, a.spotRadius,
                        a.carpetMargin) ==
               std::tie(b.length, b.width, b.lineWidth, b.centerCircleRadius, b.goalAreaDepth, b.goalAreaWidth,
                        b.penaltyAreaDepth, b.penaltyAreaWidth, b.cornerArcRadius, b.penaltyMarkDistance, b.spotRadius,
                        b.carpetMargin);
    };
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [dims, grid] : cache)
        if (same(dims, d)) return grid;
    const cv::Rect2d carpet = field.carpetBounds();
    cv::Mat grid(int(std::ceil(carpet.height / kLineStep)) + 2, int(std::ceil(carpet.width / kLineStep)) + 2, CV_32F);
    for (int gy = 0; gy < grid.rows; ++gy)
        for (int gx = 0; gx < grid.cols; ++gx)
            grid.at<float>(gy, gx) = float(field.distanceToLines({carpet.x + gx * kLineStep, carpet.y + gy * kLineStep}));
    cache.emplace_back(d, grid);
    return grid;
}

}  // namespace

// A vertical cylinder in the robot frame with the colour of its side and its top.
struct OpticsRenderer::Cylinder {
    double x = 0, y = 0, radius = 0, z0 = 0, z1 = 0;
    cv::Vec3f side, top;
    int band = 0;           // marker band colour index (robots)
    float azimuth = 0, halfWidth = 0;
};

struct OpticsRenderer::Frame {
    double cosH = 1, sinH = 0;  // heading
    RobotPose pose;
    std::vector<Cylinder> cylinders;
    cv::Vec3d ball;             // robot frame, centre
    bool ball3d = false;
    cv::Point2d ballField;
};

OpticsRenderer::OpticsRenderer(const CatadioptricCamera& camera, const FieldDimensions& field)
    : camera_(camera), field_(field)
{
    const cv::Size size = camera_.imageSize();
    const CatadioptricCameraParams& p = camera_.params();
    background_.create(size, CV_32FC3);
    background_.setTo(cv::Scalar::all(0));
    backgroundLit_ = cv::Mat::zeros(size, CV_8UC1);
    const cv::Point2d rc = camera_.rimCentre();
    const double rimPx = std::max(camera_.rimRadiusPx(), 1.0);
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            cv::Vec3f& bg = background_.at<cv::Vec3f>(y, x);
            const auto kind = camera_.kind(x, y);
            const WorldRay ray = camera_.ray(x, y);
            switch (kind) {
            case CatadioptricCamera::PixelKind::Housing: {
                // A faint glow of the housing's inner wall near the mirror's rim.
                const double rho = std::hypot(x - rc.x, y - rc.y);
                bg = kHousing * float(1.0 + 1.5 * std::exp(-std::max(rho - rimPx, 0.0) / 4.0));
                break;
            }
            case CatadioptricCamera::PixelKind::Rod: {
                bg = kRod * float(0.9 + 0.2 * std::sin(0.15 * (x + y)));
                backgroundLit_.at<uchar>(y, x) = 1;
                break;
            }
            case CatadioptricCamera::PixelKind::Mast: bg = kMast; break;
            case CatadioptricCamera::PixelKind::Body: {
                // The top plate: dark spokes, a ring of bolts, a lighter rim.
                const double t = (ray.origin[2] - p.bodyTop) / -ray.direction[2];
                const double bx = ray.origin[0] + t * ray.direction[0], by = ray.origin[1] + t * ray.direction[1];
                const double r = std::hypot(bx, by), a = std::atan2(by, bx);
                bg = kPlate;
                if (std::abs(std::sin(3 * a)) < 0.18 && r > 0.07) bg = kPlateDark;
                if (std::abs(r - 0.16) < 0.012 && std::abs(std::sin(8 * a)) < 0.25) bg = cv::Vec3f(90, 90, 96);
                if (r > p.bodyRadius - 0.02) bg = kPlate * 1.4f;
                backgroundLit_.at<uchar>(y, x) = 1;
                break;
            }
            case CatadioptricCamera::PixelKind::World: {
                WorldPixel w;
                w.offset = y * size.width + x;
                w.x = x, w.y = y;
                w.azimuth = float(std::atan2(ray.direction[1], ray.direction[0]));
                const double rho = std::hypot(x - rc.x, y - rc.y) / rimPx;
                w.vignette = float(1.0 - 0.38 * rho * rho);
                if (ray.direction[2] < -1e-5) {
                    const double t = ray.origin[2] / -ray.direction[2];
                    w.gx = float(ray.origin[0] + t * ray.direction[0]);
                    w.gy = float(ray.origin[1] + t * ray.direction[1]);
                    w.hitsFloor = std::hypot(w.gx, w.gy) < 60.0;
                    // The floor one pixel spans: from the next pixel's ray.
                    const int nx = x + 1 < size.width + camera_.margin() ? x + 1 : x - 1;
                    const WorldRay nr = camera_.ray(nx, y);
                    if (nr.direction[2] < -1e-5) {
                        const double tn = nr.origin[2] / -nr.direction[2];
                        w.footprint = float(std::hypot(nr.origin[0] + tn * nr.direction[0] - w.gx,
                                                       nr.origin[1] + tn * nr.direction[1] - w.gy));
                    }
                    w.footprint = std::max(w.footprint, 0.003f);
                }
                world_.push_back(w);
                break;
            }
            }
        }

    // Line distances and carpet shade over the carpet.
    const cv::Rect2d carpet = field_.carpetBounds();
    carpet_ = carpet;
    gridOrigin_ = {carpet.x, carpet.y};
    lineGrid_ = lineDistanceGrid(field_);
    carpetGrid_.create(int(std::ceil(carpet.height / kCarpetStep)) + 2, int(std::ceil(carpet.width / kCarpetStep)) + 2, CV_32F);
    cv::RNG rng(1977);
    rng.fill(carpetGrid_, cv::RNG::NORMAL, 0.0, 1.0);
    cv::GaussianBlur(carpetGrid_, carpetGrid_, cv::Size(), 3.0);
    cv::Scalar mean, sd;
    cv::meanStdDev(carpetGrid_, mean, sd);
    carpetGrid_ = (carpetGrid_ - mean[0]) * (0.04 / std::max(sd[0], 1e-9)) + 1.0;
    noise_.create(size.height + kNoiseMargin, size.width + kNoiseMargin, CV_32FC3);
    cv::RNG noiseRng(4242);
    noiseRng.fill(noise_, cv::RNG::NORMAL, 0.0, 1.0);
}

void OpticsRenderer::buildObjects(const OpticsScene& scene, Frame& frame) const
{
    frame.pose = scene.robot;
    frame.cosH = std::cos(scene.robot.heading);
    frame.sinH = std::sin(scene.robot.heading);
    auto add = [&](const cv::Point2d& field, double radius, double z0, double z1, cv::Vec3f side, cv::Vec3f top, int band) {
        const cv::Point2d r = toRobotFrame(scene.robot, field);
        Cylinder c;
        c.x = r.x, c.y = r.y, c.radius = radius, c.z0 = z0, c.z1 = z1, c.side = side, c.top = top, c.band = band;
        const double dist = std::hypot(r.x, r.y);
        c.azimuth = float(std::atan2(r.y, r.x));
        // Rays start up to ~5 cm off the axis.
        c.halfWidth = dist > radius + 0.06 ? float(std::asin(std::min(1.0, (radius + 0.06) / dist)) + 0.01) : float(kPi);
        frame.cylinders.push_back(c);
    };
    for (const OpticsRobot& r : scene.robots) add(r.at, r.radius, 0.0, r.height, kRobotBlack, kRobotTop, r.team);
    if (scene.feet) {
        // Two shoes pointing at the robot with jeans legs above them, 0.22 m apart.
        const cv::Point2d toRobot = cv::Point2d(scene.robot.x, scene.robot.y) - scene.feetAt;
        const double len = std::max(cv::norm(toRobot), 1e-6);
        const cv::Point2d f = toRobot / len, side(-f.y, f.x);
        for (double s : {-0.11, 0.11}) {
            const cv::Point2d leg = scene.feetAt + side * s;
            add(leg + f * 0.07, 0.065, 0.0, 0.09, kShoe, kShoe * 1.2f, 0);
            add(leg, 0.07, 0.09, 1.0, kJeans, kJeans, 0);
        }
    }
    if (scene.ballPresent) {
        const cv::Point2d b = toRobotFrame(scene.robot, scene.ball);
        frame.ball = {b.x, b.y, scene.ballRadius};
        frame.ball3d = true;
        frame.ballField = scene.ball;
    }
}

float OpticsRenderer::lightAt(const OpticsScene& scene, const Frame&, double fx, double fy, float vignette) const
{
    double l = scene.light;
    if (scene.uneven) {
        // Vignetting, a brighter hall side (+y) and a spotlight over one spot of the field.
        const double side = 0.78 + 0.3 * smoothstep(-6.0, 6.0, fy);
        const double spot = 0.45 * std::exp(-((fx - 2.5) * (fx - 2.5) + (fy + 1.0) * (fy + 1.0)) / (2 * 1.6 * 1.6));
        l *= vignette * (side + spot);
    }
    return float(l);
}

cv::Vec3f OpticsRenderer::floorColour(const OpticsScene& scene, const Frame& frame, double gx, double gy,
                                      double footprint) const
{
    const double fx = frame.pose.x + gx * frame.sinH + gy * frame.cosH;
    const double fy = frame.pose.y - gx * frame.cosH + gy * frame.sinH;
    const cv::Rect2d& carpet = carpet_;
    cv::Vec3f c;
    if (fx < carpet.x || fy < carpet.y || fx > carpet.x + carpet.width || fy > carpet.y + carpet.height) {
        if (fx < carpet.x - 4 || fy < carpet.y - 4 || fx > carpet.x + carpet.width + 4 || fy > carpet.y + carpet.height + 4)
            return kWall * float(scene.light);
        c = kHallFloor;
    } else {
        const double lx = (fx - gridOrigin_.x) * (1.0 / kLineStep), ly = (fy - gridOrigin_.y) * (1.0 / kLineStep);
        const double d = bilinear(lineGrid_, lx, ly);
        const double half = 0.5 * field_.dimensions().lineWidth;
        const float shade = bilinear(carpetGrid_, lx * (kLineStep / kCarpetStep), ly * (kLineStep / kCarpetStep));
        c = scene.carpet * shade;
        if (d < half + footprint) {
            const double white = std::clamp((half - d) / std::max(footprint, 1e-3) + 0.5, 0.0, 1.0);
            c = c * float(1 - white) + kLine * float(white);
        }
    }
    // Shadows: under the ball (contact), the robot head's, at the feet of other robots.
    double s = 1.0;
    if (frame.ball3d) {
        const double dx = gx - frame.ball[0] + 0.02, dy = gy - frame.ball[1] + 0.01;
        if (std::abs(dx) < 0.15 && std::abs(dy) < 0.15) s *= 1.0 - 0.6 * (1.0 - smoothstep(0.03, 0.15, std::sqrt(dx * dx + dy * dy)));
    }
    if (scene.headShadow) {
        const double dx = gx - scene.headShadowAt.x, dy = gy - scene.headShadowAt.y;
        if (std::abs(dx) < 0.3 && std::abs(dy) < 0.3) s *= 1.0 - 0.45 * (1.0 - smoothstep(0.14, 0.30, std::sqrt(dx * dx + dy * dy)));
    }
    for (const Cylinder& cyl : frame.cylinders) {
        if (cyl.z0 > 0) continue;
        const double dx = gx - cyl.x, dy = gy - cyl.y, reach = cyl.radius + 0.12;
        if (std::abs(dx) > reach || std::abs(dy) > reach) continue;
        const double d = std::sqrt(dx * dx + dy * dy) - cyl.radius;
        if (d < 0.12) s *= 1.0 - 0.5 * (1.0 - smoothstep(0.0, 0.12, d));
    }
    if (!scene.uneven) return c * float(s * scene.light);
    return c * float(s) * lightAt(scene, frame, fx, fy, 1.0f);
}

double OpticsRenderer::hitObjects(const Frame& frame, const WorldRay& ray, float azimuth, cv::Vec3f& colour) const
{
    double best = kInf;
    const cv::Vec3d& o = ray.origin;
    const cv::Vec3d& d = ray.direction;
    for (const Cylinder& c : frame.cylinders) {
        if (!azimuthInside(azimuth, c.azimuth, c.halfWidth)) continue;
        const double ox = o[0] - c.x, oy = o[1] - c.y;
        const double a = d[0] * d[0] + d[1] * d[1];
        const double b = ox * d[0] + oy * d[1];
        const double cc = ox * ox + oy * oy - c.radius * c.radius;
        const double disc = b * b - a * cc;
        if (disc < 0 || a < 1e-12) continue;
        const double t = (-b - std::sqrt(disc)) / a;
        if (t > 0 && t < best) {
            const double z = o[2] + t * d[2];
            if (z >= c.z0 && z <= c.z1) {
                best = t;
                // Side: a little light from the hall on the side facing us, a marker band.
                const double nx = (ox + t * d[0]) / c.radius, ny = (oy + t * d[1]) / c.radius;
                const double facing = std::max(0.0, -(nx * d[0] + ny * d[1]) / std::sqrt(a));
                colour = c.side * float(0.75 + 0.35 * facing);
                if (c.band && z > c.z1 - 0.3 && z < c.z1 - 0.2) colour = (c.band == 1 ? kCyan : kMagenta) * float(0.8 + 0.25 * facing);
                continue;
            }
        }
        if (d[2] < 0 && o[2] > c.z1) {  // through the top
            const double tt = (c.z1 - o[2]) / d[2];
            const double hx = ox + tt * d[0], hy = oy + tt * d[1];
            if (tt < best && hx * hx + hy * hy <= c.radius * c.radius) {
                best = tt;
                colour = c.top;
            }
        }
    }
    return best;
}

namespace {

// Nearest positive hit of a ray with a sphere, or inf.
double hitSphere(const WorldRay& r, const cv::Vec3d& centre, double radius)
{
    const cv::Vec3d oc = r.origin - centre;
    const double b = oc.dot(r.direction);
    const double c = oc.dot(oc) - radius * radius;
    const double disc = b * b - c;
    if (disc < 0) return kInf;
    const double t = -b - std::sqrt(disc);
    return t > 0 ? t : kInf;
}

}  // namespace

void OpticsRenderer::drawBall(const OpticsScene& scene, const Frame& frame, cv::Mat* image, cv::Mat* coverage,
                              OpticsTruth& truth) const
{
    truth.pose = scene.robot;
    if (!frame.ball3d) return;
    const cv::Vec3d B = frame.ball;
    const double R = scene.ballRadius;
    truth.xM = B[0];
    truth.yM = B[1];
    truth.distanceM = std::hypot(B[0], B[1]);
    // Bounding region: where the sphere's extreme points are seen.
    const double dist = std::max(truth.distanceM, 1e-6);
    const cv::Vec3d radial(B[0] / dist, B[1] / dist, 0), tangential(-B[1] / dist, B[0] / dist, 0);
    std::vector<cv::Point2d> corners;
    const auto centrePx = camera_.project({B[0], B[1], B[2]});
    if (!centrePx) return;
    for (const cv::Vec3d& off : {cv::Vec3d(0, 0, 0), radial * R, -radial * R, tangential * R, -tangential * R,
                                 cv::Vec3d(0, 0, R), cv::Vec3d(0, 0, -R * 0.999)}) {
        const cv::Vec3d q = B + off;
        if (auto p = camera_.project({q[0], q[1], q[2]}, *centrePx)) corners.push_back(*p);
    }
    if (corners.size() < 3) return;
    double bx0 = corners[0].x, by0 = corners[0].y, bx1 = bx0, by1 = by0;
    for (const cv::Point2d& c : corners)
        bx0 = std::min(bx0, c.x), by0 = std::min(by0, c.y), bx1 = std::max(bx1, c.x), by1 = std::max(by1, c.y);
    const cv::Rect2d bb(bx0, by0, bx1 - bx0, by1 - by0);
    const int m = camera_.margin();
    const cv::Size size = camera_.imageSize();
    const int x0 = std::max(int(std::floor(bb.x)) - 3, -m), y0 = std::max(int(std::floor(bb.y)) - 3, -m);
    const int x1 = std::min(int(std::ceil(bb.x + bb.width)) + 3, size.width + m - 2);
    const int y1 = std::min(int(std::ceil(bb.y + bb.height)) + 3, size.height + m - 2);
    if (x1 < x0 || y1 < y0) return;
    truth.box = cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1);

    // Panels turn with the spin about the vertical and a fixed tilt, so the same ball shows
    // different panels at different spots.
    const double cs = std::cos(scene.ballSpin), sn = std::sin(scene.ballSpin);
    const cv::Matx33d spin(cs, -sn, 0, sn, cs, 0, 0, 0, 1);
    const cv::Matx33d tilt(1, 0, 0, 0, std::cos(0.4), -std::sin(0.4), 0, std::sin(0.4), std::cos(0.4));
    const cv::Matx33d toBall = tilt * spin;
    const float light = lightAt(scene, frame, frame.ballField.x, frame.ballField.y,
                                1.0f);  // vignetting applied per pixel below
    const cv::Point2d rc = camera_.rimCentre();
    const double rimPx = std::max(camera_.rimRadiusPx(), 1.0);

    double area = 0, sx = 0, sy = 0, visible = 0;
    constexpr int kSub = 3;
    constexpr double kW = 1.0 / (kSub * kSub);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const auto kind = camera_.kind(x, y);
            if (kind == CatadioptricCamera::PixelKind::Housing) continue;
            const bool inFrame = x >= 0 && y >= 0 && x < size.width && y < size.height;
            const bool open = inFrame && kind == CatadioptricCamera::PixelKind::World;
            double hits = 0, seen = 0;
            std::optional<WorldRay> shadeRay;
            double shadeT = 0, shadeScore = 1e9;
            for (int j = 0; j < kSub; ++j)
                for (int i = 0; i < kSub; ++i) {
                    const double ox = (i - 1) / 3.0, oy = (j - 1) / 3.0;
                    const auto r = camera_.rayAt(x + ox, y + oy);
                    if (!r) continue;
                    const double t = hitSphere(*r, B, R);
                    if (t == kInf) continue;
                    hits += kW;
                    sx += kW * (x + ox), sy += kW * (y + oy);
                    if (!open) continue;
                    cv::Vec3f dummy;
                    const float az = float(std::atan2(r->direction[1], r->direction[0]));
                    if (hitObjects(frame, *r, az, dummy) < t) continue;
                    seen += kW;
                    const double score = std::abs(ox) + std::abs(oy);
                    if (score < shadeScore) shadeScore = score, shadeRay = r, shadeT = t;
                }
            area += hits;
            visible += seen;
            if (seen <= 0 || !shadeRay || !image) continue;
            const cv::Vec3d hit = shadeRay->origin + shadeT * shadeRay->direction;
            const cv::Vec3d n = (hit - B) / R;
            const double lambert = std::max(0.0, n.dot(kLightDir));
            const cv::Vec3f surface = ballSurfaceColor(scene.ballKind, toBall * n);
            float l = light;
            if (scene.uneven) {
                const double rho = std::hypot(x - rc.x, y - rc.y) / rimPx;
                l *= float(1.0 - 0.38 * rho * rho);
            }
            const cv::Vec3f ball = surface * float(0.32 + 0.78 * lambert) * l;
            cv::Vec3f& px = image->at<cv::Vec3f>(y, x);
            px = px * float(1 - seen) + ball * float(seen);
            if (coverage) coverage->at<float>(y, x) = float(seen);
        }
    truth.area = area;
    if (area <= 0) return;
    truth.px = sx / area;
    truth.py = sy / area;
    truth.radiusPx = std::sqrt(area / kPi);
    truth.visibleFraction = visible / area;
    const bool centreInFrame = truth.px >= 0 && truth.py >= 0 && truth.px <= size.width - 1 && truth.py <= size.height - 1;
    truth.ballVisible = centreInFrame && truth.visibleFraction >= 0.5;
}

OpticsTruth OpticsRenderer::ballTruth(const OpticsScene& scene) const
{
    Frame frame;
    buildObjects(scene, frame);
    OpticsTruth truth;
    drawBall(scene, frame, nullptr, nullptr, truth);
    return truth;
}

cv::Mat OpticsRenderer::render(const OpticsScene& scene, OpticsTruth* truthOut) const
{
    Frame frame;
    buildObjects(scene, frame);
    const cv::Size size = camera_.imageSize();
    cv::Mat image(size, CV_32FC3);
    // Static background, lit where the hall's light falls on it.
    {
        const float level = float(scene.light);
        for (int y = 0; y < size.height; ++y) {
            const cv::Vec3f* bg = background_.ptr<cv::Vec3f>(y);
            const uchar* lit = backgroundLit_.ptr<uchar>(y);
            cv::Vec3f* out = image.ptr<cv::Vec3f>(y);
            for (int x = 0; x < size.width; ++x) out[x] = lit[x] ? bg[x] * level : bg[x];
        }
    }
    auto* pixels = image.ptr<cv::Vec3f>(0);
    for (const WorldPixel& w : world_) {
        const int x = w.x, y = w.y;
        cv::Vec3f c;
        double tFloor = kInf;
        if (w.hitsFloor) {
            c = floorColour(scene, frame, w.gx, w.gy, w.footprint);
            if (scene.uneven) c *= w.vignette;
            tFloor = 0;  // replaced below only when an object is nearer
        } else {
            c = kWall * float(scene.light) * (scene.uneven ? w.vignette : 1.0f);
        }
        bool near = false;
        for (const Cylinder& cyl : frame.cylinders) near = near || azimuthInside(w.azimuth, cyl.azimuth, cyl.halfWidth);
        if (near) {
            const WorldRay ray = camera_.ray(x, y);
            if (w.hitsFloor) tFloor = ray.origin[2] / -ray.direction[2];
            cv::Vec3f oc;
            const double t = hitObjects(frame, ray, w.azimuth, oc);
            if (t < tFloor) {
                const cv::Vec3d h = ray.origin + t * ray.direction;
                const double fx = frame.pose.x + h[0] * frame.sinH + h[1] * frame.cosH;
                const double fy = frame.pose.y - h[0] * frame.cosH + h[1] * frame.sinH;
                c = oc * lightAt(scene, frame, fx, fy, w.vignette);
            }
        }
        pixels[w.offset] = c;
    }
    OpticsTruth truth;
    cv::Mat coverage;
    const bool smear = scene.motionBlurPx > 0.5;
    if (smear) coverage = cv::Mat::zeros(size, CV_32FC1);
    drawBall(scene, frame, &image, smear ? &coverage : nullptr, truth);

    if (scene.opticalBlurPx > 0) {
        // Below ~0.8 px a 3x3 kernel holds all but a trace of the Gaussian.
        const int k = scene.opticalBlurPx < 0.8 ? 3 : 2 * int(std::ceil(3 * scene.opticalBlurPx)) + 1;
        cv::GaussianBlur(image, image, cv::Size(k, k), scene.opticalBlurPx);
    }
    if (smear && truth.area > 0) {
        // Smear the ball along its motion: blend the line-filtered frame where the ball passed.
        const int len = int(std::ceil(scene.motionBlurPx));
        const cv::Rect roi = (truth.box + cv::Point(-len - 2, -len - 2) + cv::Size(2 * len + 4, 2 * len + 4)) &
                             cv::Rect(0, 0, size.width, size.height);
        if (roi.area() > 0) {
            const int k = 2 * len + 1;
            cv::Mat kernel = cv::Mat::zeros(k, k, CV_32F);
            const double c = std::cos(scene.motionAngle), s = std::sin(scene.motionAngle);
            for (int i = 0; i <= 4 * len; ++i) {
                const double t = scene.motionBlurPx * (double(i) / (4 * len) - 0.5);
                kernel.at<float>(int(std::lround(len + t * s)), int(std::lround(len + t * c))) += 1.0f;
            }
            kernel /= cv::sum(kernel)[0];
            cv::Mat blurred, weight;
            cv::filter2D(image(roi), blurred, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
            cv::filter2D(coverage(roi), weight, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
            cv::Mat w = cv::max(weight, coverage(roi)) * 1.5;
            cv::min(w, 1.0, w);
            for (int y = 0; y < roi.height; ++y) {
                cv::Vec3f* out = image.ptr<cv::Vec3f>(roi.y + y) + roi.x;
                const cv::Vec3f* b = blurred.ptr<cv::Vec3f>(y);
                const float* ww = w.ptr<float>(y);
                for (int x = 0; x < roi.width; ++x) out[x] = out[x] * (1 - ww[x]) + b[x] * ww[x];
            }
        }
    }
    if (scene.noiseSigma > 0) {
        // A window of the renderer's unit-noise table at an offset drawn from the seed: drawing
        // 0.9 M normal numbers per frame would cost more than the whole rendering.
        cv::RNG rng(scene.seed * 2654435761u + 17u);
        const int ox = rng.uniform(0, kNoiseMargin), oy = rng.uniform(0, kNoiseMargin);
        cv::scaleAdd(noise_(cv::Rect(ox, oy, size.width, size.height)), scene.noiseSigma, image, image);
    }
    cv::Mat out;
    image.convertTo(out, CV_8UC3);
    if (truthOut) *truthOut = truth;
    return out;
}

}  // namespace omnitune
