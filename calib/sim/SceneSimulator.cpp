#include "calib/sim/SceneSimulator.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace omnitune {

namespace {

// Colours (BGR), each checked against the default colour LUT (core/ColorLut.cpp): carpet is
// Green (H 60, S 182, V 140), lines White, robots and shoes Black (V < 60), markers Cyan
// (H ~92) and Magenta (H ~152); the floor beyond the carpet, jeans and the net are Unknown.
const cv::Vec3f kCarpet(40, 140, 40);
const cv::Vec3f kLine(235, 235, 235);
const cv::Vec3f kFloor(98, 108, 100);
const cv::Vec3f kRobotBlack(25, 25, 25);
const cv::Vec3f kRobotTop(34, 34, 36);
const cv::Vec3f kCyanMarker(200, 190, 20);
const cv::Vec3f kMagentaMarker(200, 30, 210);
const cv::Vec3f kShoe(38, 38, 42);
const cv::Vec3f kJeans(110, 70, 45);
const cv::Vec3f kPost(238, 238, 238);
const cv::Vec3f kNet(225, 225, 225);
const cv::Vec3f kHousing(8, 8, 8);
const cv::Vec3f kMirrorRim(40, 40, 42);
const cv::Vec3f kCameraLens(10, 10, 12);
const cv::Vec3f kLensRing(70, 70, 75);
const cv::Vec3f kRobotPlate(48, 48, 52);
const cv::Vec3f kRobotSpoke(30, 30, 32);
const cv::Vec3f kRods(45, 45, 50);

// The scene reaches a little beyond the processed ring on both sides, so that no processed
// pixel is darkened by the robot body or the mirror rim (which would hand the detector an edge
// around the whole ring). Real cameras are calibrated that way too.
constexpr double kRimMarginPx = 6.0;
constexpr double kBodyMarginPx = 2.0;

// Field textures: distance to the lines every 2 cm (bilinear is exact for straight lines),
// capped where no pixel needs it; carpet brightness every 10 cm.
constexpr double kLineGridStep = 0.02;    // m
constexpr double kLineGridCap = 0.5;      // m
constexpr double kCarpetGridStep = 0.10;  // m
constexpr double kCarpetBlotchSigma = 4.0;  // texels: ~0.4 m patches of slightly different shade
constexpr double kCarpetShadeAmplitude = 0.035;

// Light: at lightGradient = 1 the mirror rim gets 35 % darker, and the field +y side of the
// hall is 20 % brighter than the middle (the -y side 20 % darker).
constexpr double kVignetteStrength = 0.35;
constexpr double kSideLightStrength = 0.20;
constexpr double kSideLightHalfWidth = 6.0;  // m

// Robots carry their team marker as a band at this height (m).
constexpr double kMarkerLow = 0.35;
constexpr double kMarkerHigh = 0.50;

// Distractors. The head shadow is ball-sized and dark enough to leave the green class.
constexpr double kShadowRadius = 0.13;    // m
constexpr double kShadowDarkness = 0.60;  // carpet keeps 40 % of its light in the core
constexpr double kShoeLength = 0.30;      // m
constexpr double kShoeWidth = 0.12;       // m
constexpr double kFeetApart = 0.22;       // m between the shoes' centres
constexpr double kLegRadius = 0.065;      // m
constexpr double kLegHeight = 0.9;        // m, above any viewpoint: legs run out to the rim
constexpr double kNetMesh = 0.10;         // m

// The ball's panels are tilted so no panel centre sits exactly on top when ballSpin = 0.
constexpr double kBallTiltX = 0.37;  // rad about x, then
constexpr double kBallTiltY = 0.23;  // rad about y
constexpr int kBallSamples = 4;              // per pixel side: 16 samples antialias the disc

inline double clamp01(double v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }
inline double smoothstep(double e0, double e1, double x)
{
    const double t = clamp01((x - e0) / (e1 - e0));
    return t * t * (3 - 2 * t);
}
inline cv::Vec3f mix(const cv::Vec3f& a, const cv::Vec3f& b, double t)
{
    return a * float(1 - t) + b * float(t);
}

// A flat ellipse on the ground (shoe, shadow), field frame.
struct GroundEllipse {
    cv::Point2d centre;
    double semiMajor = 0, semiMinor = 0;
    double cosA = 1, sinA = 0;  // major axis direction

    GroundEllipse(cv::Point2d c, double major, double minor, double angle)
        : centre(c), semiMajor(major), semiMinor(minor), cosA(std::cos(angle)), sinA(std::sin(angle))
    {
    }
    // Normalised radius (< 1 inside), or `beyond` without the work when clearly farther.
    double radius(double x, double y, double beyond) const
    {
        const double dx = x - centre.x;
        const double dy = y - centre.y;
        const double reach = beyond * semiMajor;
        if (dx * dx + dy * dy > reach * reach) return beyond;
        const double u = (dx * cosA + dy * sinA) / semiMajor;
        const double v = (-dx * sinA + dy * cosA) / semiMinor;
        return std::sqrt(u * u + v * v);
    }
};

enum class Standing { Robot, Leg, Post };

// A vertical cylinder in the robot frame (the pixel rays start at the origin).
struct Cylinder {
    cv::Point2d c;
    double radius = 0, height = 0;
    Standing kind = Standing::Robot;
    int team = 0;
};

// A net wall in the robot frame: ground footprint a..b, height.
struct Wall {
    cv::Point2d a, b;
    double height = 0;
};

// Share of a disc of radius r cut off beyond a chord at distance s from its centre.
double segmentShare(double s, double r)
{
    const double u = std::clamp(s / r, -1.0, 1.0);
    return (std::acos(u) - u * std::sqrt(1 - u * u)) / M_PI;
}

// Chord offset s that hides `share` of a disc of radius r beyond it (bisection; monotone).
double chordForShare(double share, double r)
{
    double lo = -r, hi = r;
    for (int i = 0; i < 50; ++i) {
        const double mid = 0.5 * (lo + hi);
        (segmentShare(mid, r) > share ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Normalised line kernel of `length` px along image angle `angle` (y up), for motion blur.
cv::Mat lineKernel(double length, double angle)
{
    const int half = int(std::ceil(length / 2)) + 1;
    cv::Mat k(2 * half + 1, 2 * half + 1, CV_32F, cv::Scalar(0));
    const double dx = std::cos(angle), dy = -std::sin(angle);
    const int steps = std::max(2, int(std::ceil(length * 4)));
    for (int i = 0; i <= steps; ++i) {
        const double t = length * (double(i) / steps - 0.5);
        const double x = half + t * dx, y = half + t * dy;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        k.at<float>(y0, x0) += float((1 - fx) * (1 - fy));
        k.at<float>(y0, x0 + 1) += float(fx * (1 - fy));
        k.at<float>(y0 + 1, x0) += float((1 - fx) * fy);
        k.at<float>(y0 + 1, x0 + 1) += float(fx * fy);
    }
    return k / cv::sum(k)[0];
}

}  // namespace

SceneSimulator::SceneSimulator(const Config& config, const FieldDimensions& field)
    : geometry_(config.geometry), distanceMap_(config.distanceMap), ballModel_(config.ball), field_(field)
{
    const int w = geometry_.imageWidth;
    const int h = geometry_.imageHeight;
    if (w <= 0 || h <= 0) throw std::invalid_argument("geometry.image_width/height must be positive");
    if (!config.mask.empty() && (config.mask.cols != w || config.mask.rows != h || config.mask.type() != CV_8UC1))
        throw std::invalid_argument("simulator: the mask must be one 8-bit channel of the geometry's image size");
    if (!config.mask.empty()) mask_ = config.mask.clone();
    bodyRadius_ = std::max(0.0, geometry_.innerRadius - kBodyMarginPx);
    mirrorRadius_ = geometry_.outerRadius + kRimMarginPx;

    // Per pixel: what it sees, fixed for this camera.
    background_.create(h, w, CV_32FC3);
    ringIndex_.create(h, w, CV_32SC1);
    ringIndex_.setTo(-1);
    for (int y = 0; y < h; ++y) {
        cv::Vec3f* bg = background_.ptr<cv::Vec3f>(y);
        int* index = ringIndex_.ptr<int>(y);
        const std::uint8_t* m = mask_.empty() ? nullptr : mask_.ptr<std::uint8_t>(y);
        for (int x = 0; x < w; ++x) {
            const double dx = x - geometry_.centerX;
            const double dy = geometry_.centerY - y;  // y up
            const double rho = std::hypot(dx, dy);
            const double angle = std::atan2(dy, dx);
            if (rho > mirrorRadius_) {
                // Mirror rim, then the dark camera housing.
                bg[x] = rho < mirrorRadius_ + 3 ? kMirrorRim : kHousing;
            } else if (rho < bodyRadius_) {
                // The robot's own top seen in the mirror: camera lens, plate with spokes, bumper.
                const double rr = rho / std::max(bodyRadius_, 1.0);
                if (rr < 0.40) bg[x] = kCameraLens;
                else if (rr < 0.47) bg[x] = kLensRing;
                else if (rr < 0.80) bg[x] = std::abs(std::sin(3 * angle)) < 0.12 ? kRobotSpoke : kRobotPlate;
                else bg[x] = kRobotSpoke;
            } else if (m && m[x] == 0) {
                bg[x] = kRods * float(0.8 + 0.2 * (1 - rho / mirrorRadius_));
            } else {
                // Only blended into the ring's first and last pixel.
                bg[x] = rho > 0.5 * (bodyRadius_ + mirrorRadius_) ? kMirrorRim : kRobotSpoke;
            }
            const bool seesWorld = rho >= bodyRadius_ - 1 && rho <= mirrorRadius_ + 1;
            // The mask's structure (rods) stands in front of the world.
            if (!seesWorld || (m && m[x] == 0)) continue;
            RingPixel p;
            p.offset = y * w + x;
            p.rho = float(rho);
            p.cosA = float(rho > 0 ? dx / rho : 1.0);
            p.sinA = float(rho > 0 ? dy / rho : 0.0);
            p.ground = float(std::max(0.0, distanceMap_.toGround(rho)));
            const double radial = distanceMap_.toGround(rho + 0.5) - distanceMap_.toGround(rho - 0.5);
            const double tangential = p.ground / std::max(rho, 1.0);
            p.footprint = float(std::max(0.004, 0.5 * (radial + tangential)));
            maxGround_ = std::max(maxGround_, double(p.ground));
            index[x] = int(ring_.size());
            ring_.push_back(p);
        }
    }

    // Field textures over the carpet.
    const cv::Rect2d carpet = field_.carpetBounds();
    gridOrigin_ = {carpet.x, carpet.y};
    lineGrid_.create(int(std::ceil(carpet.height / kLineGridStep)) + 2,
                     int(std::ceil(carpet.width / kLineGridStep)) + 2, CV_32F);
    lineGrid_.setTo(kLineGridCap);
    // Each line only touches the texels in its bounding box (plus the cap): cheap to stamp.
    const auto stamp = [&](cv::Point2d lo, cv::Point2d hi, auto distance) {
        const int i0 = std::max(0, int(std::floor((lo.x - kLineGridCap - gridOrigin_.x) / kLineGridStep)));
        const int i1 = std::min(lineGrid_.cols - 1, int(std::ceil((hi.x + kLineGridCap - gridOrigin_.x) / kLineGridStep)));
        const int j0 = std::max(0, int(std::floor((lo.y - kLineGridCap - gridOrigin_.y) / kLineGridStep)));
        const int j1 = std::min(lineGrid_.rows - 1, int(std::ceil((hi.y + kLineGridCap - gridOrigin_.y) / kLineGridStep)));
        for (int j = j0; j <= j1; ++j) {
            float* row = lineGrid_.ptr<float>(j);
            for (int i = i0; i <= i1; ++i) {
                const cv::Point2d p(gridOrigin_.x + i * kLineGridStep, gridOrigin_.y + j * kLineGridStep);
                row[i] = std::min(row[i], float(distance(p)));
            }
        }
    };
    for (const FieldSegment& s : field_.segments())
        stamp({std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)}, {std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)},
              [&](const cv::Point2d& p) { return FieldModel::distanceTo(s, p); });
    for (const FieldArc& a : field_.arcs()) {
        const cv::Point2d r(a.radius, a.radius);
        stamp(a.centre - r, a.centre + r, [&](const cv::Point2d& p) { return FieldModel::distanceTo(a, p); });
    }
    const double spotInset = field_.dimensions().spotRadius - 0.5 * field_.dimensions().lineWidth;
    for (const cv::Point2d& c : field_.spots()) {
        const cv::Point2d r(spotInset, spotInset);
        stamp(c - r, c + r, [&](const cv::Point2d& p) { return std::max(0.0, cv::norm(p - c) - spotInset); });
    }

    // Carpet shade: smooth blotches from a fixed seed, so every frame shows the same carpet.
    carpetGrid_.create(int(std::ceil(carpet.height / kCarpetGridStep)) + 2,
                       int(std::ceil(carpet.width / kCarpetGridStep)) + 2, CV_32F);
    cv::RNG carpetRng(2009);
    carpetRng.fill(carpetGrid_, cv::RNG::NORMAL, 0.0, 1.0);
    cv::GaussianBlur(carpetGrid_, carpetGrid_, cv::Size(), kCarpetBlotchSigma);
    cv::Scalar mean, stddev;
    cv::meanStdDev(carpetGrid_, mean, stddev);
    carpetGrid_ = (carpetGrid_ - mean[0]) * (kCarpetShadeAmplitude / std::max(stddev[0], 1e-9)) + 1.0;
}

double SceneSimulator::lineDistance(double fx, double fy) const
{
    const double gx = (fx - gridOrigin_.x) / kLineGridStep;
    const double gy = (fy - gridOrigin_.y) / kLineGridStep;
    const int ix = int(std::floor(gx));
    const int iy = int(std::floor(gy));
    if (ix < 0 || iy < 0 || ix + 1 >= lineGrid_.cols || iy + 1 >= lineGrid_.rows) return kLineGridCap;
    const double tx = gx - ix, ty = gy - iy;
    const float* r0 = lineGrid_.ptr<float>(iy) + ix;
    const float* r1 = lineGrid_.ptr<float>(iy + 1) + ix;
    return (1 - ty) * ((1 - tx) * r0[0] + tx * r0[1]) + ty * ((1 - tx) * r1[0] + tx * r1[1]);
}

double SceneSimulator::carpetShade(double fx, double fy) const
{
    const double gx = (fx - gridOrigin_.x) / kCarpetGridStep;
    const double gy = (fy - gridOrigin_.y) / kCarpetGridStep;
    const int ix = int(std::floor(gx));
    const int iy = int(std::floor(gy));
    if (ix < 0 || iy < 0 || ix + 1 >= carpetGrid_.cols || iy + 1 >= carpetGrid_.rows) return 1.0;
    const double tx = gx - ix, ty = gy - iy;
    const float* r0 = carpetGrid_.ptr<float>(iy) + ix;
    const float* r1 = carpetGrid_.ptr<float>(iy + 1) + ix;
    return (1 - ty) * ((1 - tx) * r0[0] + tx * r0[1]) + ty * ((1 - tx) * r1[0] + tx * r1[1]);
}

GroundTruth SceneSimulator::groundTruth(const SceneOptions& scene) const
{
    GroundTruth t;
    t.pose = scene.robot;
    if (!scene.ballPresent) return t;
    const cv::Point2d b = toRobotFrame(scene.robot, {scene.ballX, scene.ballY});
    t.xM = b.x;
    t.yM = b.y;
    t.distanceM = std::hypot(b.x, b.y);
    t.distancePx = distanceMap_.ballPixels(t.distanceM);
    t.radiusPx = ballModel_.radiusAt(t.distancePx);
    const double angle = std::atan2(b.y, b.x);
    t.px = geometry_.centerX + t.distancePx * std::cos(angle);
    t.py = geometry_.centerY - t.distancePx * std::sin(angle);
    // The part of the disc inside the processed ring, by sampling.
    int inside = 0, total = 0;
    const double r = t.radiusPx;
    for (double v = -r; v <= r; v += 0.25)
        for (double u = -r; u <= r; u += 0.25) {
            if (u * u + v * v > r * r) continue;
            ++total;
            const double rho = std::hypot(t.px + u - geometry_.centerX, t.py + v - geometry_.centerY);
            inside += rho >= geometry_.innerRadius && rho <= geometry_.outerRadius;
        }
    t.visibleFraction = total ? double(inside) / total : 0.0;
    t.ballVisible = t.visibleFraction >= 0.5 && t.px >= 0 && t.py >= 0 && t.px < geometry_.imageWidth &&
                    t.py < geometry_.imageHeight;
    return t;
}

// One render's working state.
struct SceneSimulator::Frame {
    explicit Frame(const SceneOptions& s) : scene(s) {}
    const SceneOptions& scene;
    std::vector<GroundEllipse> shadows;  // flat, on the ground
    std::vector<GroundEllipse> shoes;
    std::vector<Cylinder> cylinders;     // standing, robot frame
    std::vector<Wall> walls;
    cv::Mat canvas;                      // CV_32FC3, linear BGR before blur and noise
    std::vector<float> light;            // per ring pixel: the light factor there
    std::vector<float> hit;              // per ring pixel: ground distance of the nearest opaque
                                         // standing thing on its ray (infinity: none)
};

cv::Mat SceneSimulator::render(const SceneOptions& scene, GroundTruth* truth) const
{
    Frame f(scene);
    placeThings(f);
    shadeWorld(f);
    GroundTruth t = groundTruth(scene);
    if (scene.ballPresent && t.distancePx < mirrorRadius_ + t.radiusPx) drawBall(f, t);
    if (truth) *truth = t;

    // Lens blur, sensor noise, then 8 bits.
    if (scene.opticalBlurPx > 0) cv::GaussianBlur(f.canvas, f.canvas, cv::Size(), scene.opticalBlurPx);
    if (scene.noiseSigma > 0) {
        cv::Mat noise(f.canvas.size(), CV_32FC3);
        cv::RNG rng(scene.seed);
        rng.fill(noise, cv::RNG::NORMAL, 0.0, scene.noiseSigma);
        f.canvas += noise;
    }
    cv::Mat frame;
    f.canvas.convertTo(frame, CV_8UC3);
    return frame;
}

void SceneSimulator::placeThings(Frame& f) const
{
    const SceneOptions& scene = f.scene;
    const RobotPose& pose = scene.robot;

    // Distractor spots chosen from the seed (always drawn, so one flag does not move the other).
    cv::RNG pick(0x5eed0000ull + scene.seed);
    const double shadowDistance = pick.uniform(0.55, 1.0);
    const double shadowAngle = pick.uniform(0.0, 2 * M_PI);
    const double shadowAspect = pick.uniform(1.0, 1.3);
    const double shadowTilt = pick.uniform(0.0, M_PI);
    const double feetDistance = pick.uniform(1.2, 2.2);
    const double feetAngle = pick.uniform(0.0, 2 * M_PI);
    const double feetTurn = pick.uniform(-0.6, 0.6);

    if (scene.headShadow) {
        const cv::Point2d off = scene.shadowOffset.value_or(
            cv::Point2d(shadowDistance * std::cos(shadowAngle), shadowDistance * std::sin(shadowAngle)));
        f.shadows.push_back({{pose.x + off.x, pose.y + off.y}, kShadowRadius * shadowAspect, kShadowRadius, shadowTilt});
    }
    if (scene.humanFeet) {
        const cv::Point2d at = scene.feetAt.value_or(cv::Point2d(
            pose.x + feetDistance * std::cos(feetAngle), pose.y + feetDistance * std::sin(feetAngle)));
        // The person faces the robot, roughly; toes point that way, legs stand on the heels.
        const double facing = std::atan2(pose.y - at.y, pose.x - at.x) + feetTurn;
        const cv::Point2d fwd(std::cos(facing), std::sin(facing));
        const cv::Point2d side(-fwd.y, fwd.x);
        for (double s : {-0.5, 0.5}) {
            const cv::Point2d c = at + s * kFeetApart * side;
            f.shoes.push_back({c, kShoeLength / 2, kShoeWidth / 2, facing});
            const cv::Point2d heel = c - 0.35 * kShoeLength * fwd;
            f.cylinders.push_back({toRobotFrame(pose, heel), kLegRadius, kLegHeight, Standing::Leg, 0});
        }
    }
    for (const ObstacleRobot& o : scene.obstacles)
        f.cylinders.push_back({toRobotFrame(pose, {o.x, o.y}), o.radius, o.height, Standing::Robot, o.team});
    for (const FieldGoal& goal : field_.goals()) {
        for (const cv::Point2d& post : {goal.leftPost, goal.rightPost})
            f.cylinders.push_back({toRobotFrame(pose, post), goal.postRadius, goal.height, Standing::Post, 0});
        for (const FieldSegment& s : goal.net)
            f.walls.push_back({toRobotFrame(pose, s.a), toRobotFrame(pose, s.b), goal.height});
    }
    // Nothing beyond the farthest ground a pixel sees can appear; skip it per pixel.
    const auto outOfSight = [&](const Cylinder& c) {
        const double d = cv::norm(c.c);
        return d - c.radius > maxGround_ || d <= c.radius;  // (or we stand inside it)
    };
    f.cylinders.erase(std::remove_if(f.cylinders.begin(), f.cylinders.end(), outOfSight), f.cylinders.end());
    const auto wallOutOfSight = [&](const Wall& wl) {
        return FieldModel::distanceTo(FieldSegment{wl.a, wl.b}, {0, 0}) > maxGround_;
    };
    f.walls.erase(std::remove_if(f.walls.begin(), f.walls.end(), wallOutOfSight), f.walls.end());
}

void SceneSimulator::shadeWorld(Frame& f) const
{
    const SceneOptions& scene = f.scene;
    const RobotPose& pose = scene.robot;
    const double H = distanceMap_.options().viewpointHeight;
    const double cosH = std::cos(pose.heading);
    const double sinH = std::sin(pose.heading);
    const double g = std::clamp(scene.lightGradient, 0.0, 1.0);
    f.canvas = background_.clone();
    cv::Vec3f* out = f.canvas.ptr<cv::Vec3f>();
    const cv::Vec3f* bg = background_.ptr<cv::Vec3f>();
    f.light.assign(ring_.size(), 1.0f);
    f.hit.assign(ring_.size(), std::numeric_limits<float>::infinity());
    const double halfLine = 0.5 * field_.dimensions().lineWidth;

    for (std::size_t i = 0; i < ring_.size(); ++i) {
        const RingPixel& rp = ring_[i];
        const double ux = rp.cosA, uy = rp.sinA;
        const double D = rp.ground;
        const double fp = rp.footprint;
        const double fx = pose.x + D * (ux * sinH + uy * cosH);
        const double fy = pose.y + D * (-ux * cosH + uy * sinH);

        // The ground.
        cv::Vec3f col;
        if (field_.onCarpet({fx, fy})) {
            col = kCarpet * float(carpetShade(fx, fy));
            const double cover = clamp01((halfLine - lineDistance(fx, fy)) / fp + 0.5);
            if (cover > 0) col = mix(col, kLine, cover);
        } else {
            col = kFloor;
        }
        for (const GroundEllipse& s : f.shadows) {
            const double q = s.radius(fx, fy, 1.3);
            if (q < 1.3) col *= float(1 - kShadowDarkness * (1 - smoothstep(0.7, 1.25, q)));
        }
        for (const GroundEllipse& s : f.shoes) {
            const double q = s.radius(fx, fy, 2.0);
            if (q < 2) col = mix(col, kShoe * float(0.85 + 0.15 * q), clamp01((1 - q) * s.semiMinor / fp + 0.5));
        }

        // Standing things, nearest first: a pixel whose ray meets one before reaching the ground
        // sees it at height z = H (1 - t / D).
        double nearest = std::numeric_limits<double>::infinity();
        cv::Vec3f thing;
        double thingCover = 0;
        for (const Cylinder& c : f.cylinders) {
            const double proj = ux * c.c.x + uy * c.c.y;
            if (proj <= 0) continue;
            const double perp = ux * c.c.y - uy * c.c.x;
            const double slack = proj / std::max(double(rp.rho), 1.0);  // m per px across the ray there
            if (std::abs(perp) >= c.radius + 0.5 * slack) continue;
            const double p = std::min(std::abs(perp), c.radius);
            const double chord = std::sqrt(c.radius * c.radius - p * p);
            const double t = proj - chord;
            if (t >= D + 0.5 * fp || t >= nearest) continue;
            const double z = H * (1 - t / std::max(D, 1e-6));
            const double facing = chord / c.radius;
            cv::Vec3f cc;
            if (z > c.height) {
                // The ray passes over the near face; it may still come down on the top.
                const double tTop = D * (1 - c.height / H);
                if (c.height >= H || tTop > proj + chord) continue;
                cc = kRobotTop;
            } else if (c.kind == Standing::Robot) {
                const bool band = c.team != 0 && z >= kMarkerLow && z <= kMarkerHigh;
                cc = band ? (c.team == 1 ? kCyanMarker : kMagentaMarker) * float(0.7 + 0.3 * facing)
                          : kRobotBlack * float(0.75 + 0.35 * facing);
            } else if (c.kind == Standing::Leg) {
                cc = kJeans * float(0.65 + 0.35 * facing);
            } else {
                cc = kPost * float(0.75 + 0.25 * facing);
            }
            nearest = t;
            thing = cc;
            thingCover = clamp01((c.radius - std::abs(perp)) / std::max(slack, 1e-6) + 0.5) *
                         clamp01((D - t) / fp + 0.5);
        }
        if (thingCover > 0) col = mix(col, thing, thingCover);
        f.hit[i] = thingCover >= 0.5 ? float(nearest) : std::numeric_limits<float>::infinity();

        // Goal nets: see-through mesh in front of whatever is behind.
        for (const Wall& wl : f.walls) {
            const cv::Point2d e = wl.b - wl.a;
            const double denom = ux * e.y - uy * e.x;
            if (std::abs(denom) < 1e-12) continue;
            const double t = (wl.a.x * e.y - wl.a.y * e.x) / denom;
            const double s = (wl.a.x * uy - wl.a.y * ux) / denom;
            if (t <= 0 || t >= D || t >= nearest || s < 0 || s > 1) continue;
            const double z = H * (1 - t / D);
            if (z > wl.height) continue;
            const double along = s * cv::norm(e) / kNetMesh;
            const double up = z / kNetMesh;
            const bool strand = along - std::floor(along) < 0.2 || up - std::floor(up) < 0.2;
            col = mix(col, kNet, strand ? 0.55 : 0.15);
        }

        // Light: global level, vignetting towards the rim, a brighter +y side of the hall.
        const double rr = rp.rho / geometry_.outerRadius;
        const double lit = scene.lightLevel * (1 - kVignetteStrength * g * rr * rr) *
                           (1 + kSideLightStrength * g * std::clamp(fy / kSideLightHalfWidth, -1.0, 1.0));
        f.light[i] = float(lit);
        col *= float(lit);

        // Blend into the robot body and the mirror rim over one pixel.
        const double alpha = clamp01(rp.rho - bodyRadius_ + 0.5) * clamp01(mirrorRadius_ + 0.5 - rp.rho);
        out[rp.offset] = alpha >= 1 ? col : mix(bg[rp.offset], col, alpha);
    }
}

void SceneSimulator::drawBall(Frame& f, GroundTruth& t) const
{
    const SceneOptions& scene = f.scene;
    const RobotPose& pose = scene.robot;
    const int w = geometry_.imageWidth;
    const int h = geometry_.imageHeight;
    const double H = distanceMap_.options().viewpointHeight;
    cv::Vec3f* out = f.canvas.ptr<cv::Vec3f>();
    const double r = t.radiusPx;
    const double blur = std::max(0.0, scene.motionBlurPx);
    const double erx = (t.px - geometry_.centerX) / std::max(t.distancePx, 1e-9);
    const double ery = (t.py - geometry_.centerY) / std::max(t.distancePx, 1e-9);
    const double etx = ery, ety = -erx;  // counter-clockwise on screen (y up)

    // The sphere as seen from the viewpoint: view direction v, "outward in the image" p
    // (away from the robot and up), tangential q, all in field axes with z up.
    const double H_b = H - distanceMap_.options().ballRadius;
    const double elevation = std::atan2(H_b, t.distanceM);
    cv::Point2d a(scene.ballX - pose.x, scene.ballY - pose.y);
    a = t.distanceM > 1e-9 ? a / t.distanceM : cv::Point2d(1, 0);
    const double ce = std::cos(elevation), se = std::sin(elevation);
    const cv::Vec3d v(-a.x * ce, -a.y * ce, se);
    const cv::Vec3d p(a.x * se, a.y * se, ce);
    const cv::Vec3d q(-a.y, a.x, 0);
    const double tcx = std::cos(kBallTiltX), tsx = std::sin(kBallTiltX);
    const double tcy = std::cos(kBallTiltY), tsy = std::sin(kBallTiltY);
    const cv::Matx33d tilt = cv::Matx33d(tcy, 0, tsy, 0, 1, 0, -tsy, 0, tcy) * cv::Matx33d(1, 0, 0, 0, tcx, -tsx, 0, tsx, tcx);
    const double cs = std::cos(scene.ballSpin), ss = std::sin(scene.ballSpin);
    const cv::Matx33d spinInverse(cs, ss, 0, -ss, cs, 0, 0, 0, 1);
    const cv::Matx33d toBall = tilt.t() * spinInverse;

    // Premultiplied colour and coverage in a patch around the ball.
    const int half = int(std::ceil(r + blur / 2)) + 3;
    const int x0 = int(std::lround(t.px)) - half;
    const int y0 = int(std::lround(t.py)) - half;
    cv::Mat patch(2 * half + 1, 2 * half + 1, CV_32FC4, cv::Scalar::all(0));
    for (int j = 0; j < patch.rows; ++j) {
        cv::Vec4f* row = patch.ptr<cv::Vec4f>(j);
        for (int i = 0; i < patch.cols; ++i) {
            const double cx = x0 + i - t.px, cy = y0 + j - t.py;
            if (std::hypot(cx, cy) > r + 1) continue;
            cv::Vec3f sum(0, 0, 0);
            int inside = 0;
            for (int sj = 0; sj < kBallSamples; ++sj)
                for (int si = 0; si < kBallSamples; ++si) {
                    const double dx = cx + (si + 0.5) / kBallSamples - 0.5;
                    const double dy = cy + (sj + 0.5) / kBallSamples - 0.5;
                    const double u = (dx * erx + dy * ery) / r;
                    const double s = (dx * etx + dy * ety) / r;
                    const double q2 = u * u + s * s;
                    if (q2 > 1) continue;
                    const double wv = std::sqrt(1 - q2);
                    const cv::Vec3d n = u * p + s * q + wv * v;
                    const double shade = std::min(1.0, 0.70 + 0.18 * std::max(0.0, n[2]) + 0.14 * wv);
                    sum += ballSurfaceColor(scene.ball, toBall * n) * float(shade);
                    ++inside;
                }
            const float k = 1.0f / float(kBallSamples * kBallSamples);
            row[i] = cv::Vec4f(sum[0] * k, sum[1] * k, sum[2] * k, float(inside) * k);
        }
    }
    if (blur > 0.5) cv::filter2D(patch, patch, -1, lineKernel(blur, scene.motionAngle), cv::Point(-1, -1), 0,
                                 cv::BORDER_CONSTANT);

    // The occluder: a black robot edge, radial in the image, coming from the
    // counter-clockwise side and hiding `occlusion` of the disc.
    const double occlusion = std::clamp(scene.occlusion, 0.0, 1.0);
    const double chord = occlusion >= 1 ? -r - 1 : chordForShare(occlusion, r);
    const double occluderWidth = std::max(3 * r, 12.0);
    const double occluderStart =
        distanceMap_.toPixels(std::max(0.8 * t.distanceM, distanceMap_.toGround(geometry_.innerRadius))) -
        t.distancePx;
    const auto occluderCover = [&](double dx, double dy) {
        if (occlusion <= 0) return 0.0;
        const double u = dx * erx + dy * ery;
        const double s = dx * etx + dy * ety;
        return clamp01(s - chord + 0.5) * clamp01(chord + occluderWidth - s + 0.5) * clamp01(u - occluderStart + 0.5);
    };

    double all = 0, seen = 0;
    for (int j = 0; j < patch.rows; ++j) {
        const int y = y0 + j;
        const cv::Vec4f* row = patch.ptr<cv::Vec4f>(j);
        for (int i = 0; i < patch.cols; ++i) {
            const int x = x0 + i;
            const float alpha = row[i][3];
            if (alpha <= 0) continue;
            all += alpha;
            if (x < 0 || y < 0 || x >= w || y >= h) continue;
            const int idx = ringIndex_.at<int>(y, x);
            if (idx < 0 || f.hit[std::size_t(idx)] < t.distanceM) continue;  // body, rim, rods, obstacle
            const float lit = f.light[std::size_t(idx)];
            cv::Vec3f& o = out[y * w + x];
            o = o * (1 - alpha) + cv::Vec3f(row[i][0], row[i][1], row[i][2]) * lit;
            seen += alpha * (1 - occluderCover(x - t.px, y - t.py));
        }
    }
    t.visibleFraction = all > 0 ? seen / all : 0.0;
    t.ballVisible = t.visibleFraction >= 0.5 && t.px >= 0 && t.py >= 0 && t.px < w && t.py < h;

    if (occlusion > 0) {
        // The occluder's box: from its near face out past the mirror rim.
        const double reach = mirrorRadius_ - t.distancePx + 2;
        std::array<cv::Point2d, 4> corners;
        int k = 0;
        for (double u : {occluderStart, reach})
            for (double s : {chord, chord + occluderWidth})
                corners[std::size_t(k++)] = {t.px + u * erx + s * etx, t.py + u * ery + s * ety};
        int bx0 = w, by0 = h, bx1 = -1, by1 = -1;
        for (const cv::Point2d& c : corners) {
            bx0 = std::min(bx0, int(std::floor(c.x)) - 1);
            by0 = std::min(by0, int(std::floor(c.y)) - 1);
            bx1 = std::max(bx1, int(std::ceil(c.x)) + 1);
            by1 = std::max(by1, int(std::ceil(c.y)) + 1);
        }
        for (int y = std::max(0, by0); y <= std::min(h - 1, by1); ++y)
            for (int x = std::max(0, bx0); x <= std::min(w - 1, bx1); ++x) {
                const int idx = ringIndex_.at<int>(y, x);
                if (idx < 0) continue;
                const double cover = occluderCover(x - t.px, y - t.py);
                if (cover <= 0) continue;
                cv::Vec3f& o = out[y * w + x];
                o = mix(o, kRobotBlack * f.light[std::size_t(idx)], cover);
            }
    }
}

}  // namespace omnitune
