#include "calib/sim/optics/OpticsCell.h"

#include "calib/sim/optics/OpticsMeasurement.h"
#include "core/ConfigWriter.h"
#include "core/Pi.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>

namespace omnitune {

std::string opticsLightName(OpticsLight light)
{
    switch (light) {
    case OpticsLight::Dim: return "dim";
    case OpticsLight::Normal: return "normal";
    case OpticsLight::Bright: return "bright";
    case OpticsLight::Uneven: return "uneven";
    }
    return "normal";
}

std::string opticsDistractorsName(OpticsDistractors distractors)
{
    switch (distractors) {
    case OpticsDistractors::None: return "none";
    case OpticsDistractors::RobotsFeetShadow: return "robots";
    case OpticsDistractors::NoiseBlur: return "noise";
    case OpticsDistractors::RodsOcclusion: return "rods";
    }
    return "none";
}

std::string opticsCarpetName(OpticsCarpet carpet)
{
    switch (carpet) {
    case OpticsCarpet::Green: return "green";
    case OpticsCarpet::CyanGreen: return "cyan-green";
    case OpticsCarpet::DarkGreen: return "dark-green";
    case OpticsCarpet::Teal: return "teal";
    }
    return "green";
}

std::string opticsMirrorName(OpticsMirror mirror)
{
    return mirror == OpticsMirror::Spherical ? "spherical" : "hyperbolic";
}

std::string opticsCellName(const OpticsCell& cell)
{
    std::string name = std::string(ballKindName(cell.ball)) + "/" + opticsLightName(cell.light) + "/" +
                       opticsDistractorsName(cell.distractors) + "/" + std::to_string(cell.image.width) + "x" +
                       std::to_string(cell.image.height);
    if (cell.carpet != OpticsCarpet::Green) name += "/" + opticsCarpetName(cell.carpet);
    if (cell.mirror != OpticsMirror::Hyperbolic) name += "/" + opticsMirrorName(cell.mirror);
    if (!cell.ballPresent) name += "/no-ball";
    return name;
}

namespace {

// FNV-1a: a hash that is the same on every build, so a cell's scenes do not depend on the library.
std::uint64_t stableHash(const std::string& text)
{
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    return h;
}

struct CameraEntry {
    std::unique_ptr<CatadioptricCamera> camera;
    std::unique_ptr<OpticsRenderer> renderer;
    CameraMeasurements measurements;
    std::map<std::string, std::shared_ptr<const MeasuredCalibration>> calibrations;  // by base config text
};

std::mutex& cacheMutex()
{
    static std::mutex m;
    return m;
}

std::map<std::string, std::shared_ptr<CameraEntry>>& cache()
{
    static std::map<std::string, std::shared_ptr<CameraEntry>> c;
    return c;
}

cv::Vec3f carpetColour(OpticsCarpet carpet)
{
    switch (carpet) {
    case OpticsCarpet::Green: return {40, 140, 40};
    case OpticsCarpet::CyanGreen: return {100, 150, 35};  // hue ~83 deg: a blue-ish artificial turf
    case OpticsCarpet::DarkGreen: return {32, 92, 30};    // a worn, dark hall carpet
    case OpticsCarpet::Teal: return {140, 145, 35};       // hue ~88: past the default green box
    }
    return {40, 140, 40};
}

// A ball beyond the carpet is out of play, and no team asks the detector for it: slide the whole
// scene (our robot, the ball, the others, the feet) by the least translation that puts the ball,
// all of it, on the carpet. Everything seen from our robot stays as it was drawn.
void keepBallOnCarpet(OpticsScene& s, const FieldModel& field)
{
    const cv::Rect2d carpet = field.carpetBounds();
    const double r = s.ballRadius;
    const double x = std::clamp(s.ball.x, carpet.x + r, carpet.x + carpet.width - r);
    const double y = std::clamp(s.ball.y, carpet.y + r, carpet.y + carpet.height - r);
    const cv::Point2d shift(x - s.ball.x, y - s.ball.y);
    s.robot.x += shift.x;
    s.robot.y += shift.y;
    s.ball += shift;
    s.feetAt += shift;
    for (OpticsRobot& other : s.robots) other.at += shift;
}

}  // namespace

int opticsCellRods(const OpticsCell& cell)
{
    if (cell.distractors != OpticsDistractors::RodsOcclusion) return 0;
    return cell.image.width == cell.image.height ? 4 : 3;
}

CatadioptricCameraParams opticsCellCameraParams(const OpticsCell& cell)
{
    return cell.mirror == OpticsMirror::Spherical ? sphericalCameraParams(cell.image, opticsCellRods(cell))
                                                   : hyperbolicCameraParams(cell.image, opticsCellRods(cell));
}

OpticsCamera opticsCellCamera(const OpticsCell& cell, const Config& base)
{
    const CatadioptricCameraParams params = opticsCellCameraParams(cell);
    std::shared_ptr<CameraEntry> entry;
    {
        std::lock_guard<std::mutex> lock(cacheMutex());
        auto& slot = cache()[params.name];
        if (!slot) {
            slot = std::make_shared<CameraEntry>();
            slot->camera = std::make_unique<CatadioptricCamera>(params);
            slot->renderer = std::make_unique<OpticsRenderer>(*slot->camera);
            slot->measurements = measureOpticsCamera(*slot->renderer);
        }
        entry = slot;
    }
    OpticsCamera out;
    out.renderer = entry->renderer.get();
    out.measurements = &entry->measurements;
    const std::string key = serializeConfig(base);
    std::lock_guard<std::mutex> lock(cacheMutex());
    auto& cal = entry->calibrations[key];
    if (!cal) cal = std::make_shared<const MeasuredCalibration>(calibrateFromMeasurements(base, entry->measurements));
    out.calibration = cal;
    return out;
}

OpticsScene opticsCellScene(const OpticsCell& cell, int frame, const OpticsRenderer& renderer)
{
    std::string conditions = opticsCellName(cell);
    cv::RNG rng(stableHash(conditions) ^ (std::uint64_t(cell.seed) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(frame) * 7919u));
    OpticsScene s;
    s.seed = cell.seed * 100003u + unsigned(frame);
    s.ballKind = cell.ball;
    s.ballPresent = cell.ballPresent;
    s.carpet = carpetColour(cell.carpet);
    s.ballSpin = rng.uniform(0.0, 2 * kPi);
    s.robot = {rng.uniform(-6.0, 6.0), rng.uniform(-3.5, 3.5), rng.uniform(-kPi, kPi)};
    switch (cell.light) {
    case OpticsLight::Dim: s.light = 0.35, s.noiseSigma = 3.0; break;  // the camera's gain is up
    case OpticsLight::Normal: s.light = 1.0; break;
    case OpticsLight::Bright: s.light = 1.6; break;
    case OpticsLight::Uneven: s.light = 1.0, s.uneven = true; break;
    }

    // The ball: distances spread 0.5..5 m over the frames, directions all around.
    const int n = std::max(cell.frames, 1);
    const double u = (frame + rng.uniform(0.15, 0.85)) / n;
    double dist = 0.5 + 4.5 * u;
    const bool random = cell.directions == OpticsDirections::Random;
    double az = random ? rng.uniform(0.0, 2 * kPi) : 2 * kPi * std::fmod(frame * 0.618034 + rng.uniform(0.0, 0.15), 1.0);
    // Which of a distractor's three situations the frame shows (the ball on a line; behind a rod,
    // behind a robot, at our body): in turn, or drawn, so that one-frame cells meet them all.
    const int situation = random ? rng.uniform(0, 3) : frame % 3;
    auto ballAt = [&](double d, double a) { return toFieldFrame(s.robot, {d * std::cos(a), d * std::sin(a)}); };

    switch (cell.distractors) {
    case OpticsDistractors::None: break;
    case OpticsDistractors::RobotsFeetShadow: {
        // Two robots and a person somewhere around, the head's shadow; every third ball touches a line.
        for (int k = 0; k < 2; ++k) {
            const double a = az + rng.uniform(0.8, 5.4), d = rng.uniform(1.0, 4.5);
            s.robots.push_back({toFieldFrame(s.robot, {d * std::cos(a), d * std::sin(a)}), 0.25, rng.uniform(0.6, 0.8), 1 + k % 2});
        }
        const double fa = az + rng.uniform(1.0, 5.2), fd = rng.uniform(1.0, 2.5);
        s.feet = true;
        s.feetAt = toFieldFrame(s.robot, {fd * std::cos(fa), fd * std::sin(fa)});
        s.headShadow = true;
        const double sa = rng.uniform(0.0, 2 * kPi), sd = rng.uniform(0.55, 0.9);
        s.headShadowAt = {sd * std::cos(sa), sd * std::sin(sa)};
        if (situation == 1) {
            // Robot beside the halfway line, the ball touching it.
            s.robot.x = rng.uniform(-1.5, -0.5) * (rng.uniform(0, 2) ? 1 : -1);
            const cv::Point2d onLine(0.0625 + 0.11 + 0.005, s.robot.y + rng.uniform(-2.0, 2.0));
            s.ball = {s.robot.x < 0 ? -onLine.x : onLine.x, onLine.y};
            const cv::Point2d r = toRobotFrame(s.robot, s.ball);
            dist = std::hypot(r.x, r.y);
            az = std::atan2(r.y, r.x);
        }
        break;
    }
    case OpticsDistractors::NoiseBlur:
        s.noiseSigma = std::max(s.noiseSigma, 6.0);
        s.opticalBlurPx = 0.9;
        s.motionBlurPx = 7.0;
        s.motionAngle = rng.uniform(0.0, kPi);
        break;
    case OpticsDistractors::RodsOcclusion: {
        // The first search step that leaves 55..85 % of the silhouette unhidden wins; the
        // steps are shuffled by the frame so the hidden side varies.
        auto visibleShare = [&](const OpticsScene& trial) { return renderer.ballTruth(trial).visibleFraction; };
        const int kind = situation;
        const double sign = rng.uniform(0, 2) ? 1.0 : -1.0;
        if (kind == 0) {
            // Partly behind a rod: find where a rod crosses the ball's distance, then slide off it.
            dist = std::max(dist, 1.8);
            const CatadioptricCamera& camera = renderer.camera();
            const double from = random ? az : 0.0;
            for (double a = from; a < from + 2 * kPi; a += 0.004) {
                const auto p = camera.project({dist * std::cos(a), dist * std::sin(a), 0.11});
                if (!p) continue;
                const int x = int(std::lround(p->x)), y = int(std::lround(p->y));
                if (camera.inTable(x, y) && camera.kind(x, y) == CatadioptricCamera::PixelKind::Rod) {
                    for (double off = 0.0; off < 0.6; off += 0.01) {
                        OpticsScene trial = s;
                        trial.ball = ballAt(dist, a + sign * off / dist);
                        const double v = visibleShare(trial);
                        if (v >= 0.55 && v <= 0.85) {
                            az = a + sign * off / dist;
                            break;
                        }
                    }
                    break;
                }
            }
        } else if (kind == 1) {
            // Partly behind another robot standing between.
            dist = std::max(dist, 1.6);
            const double rd = dist - 0.7;
            for (double side = 0.1; side < 0.6; side += 0.01) {
                OpticsScene trial = s;
                const double ra = az + sign * side / rd;
                trial.robots.push_back({toFieldFrame(s.robot, {rd * std::cos(ra), rd * std::sin(ra)}), 0.25, 0.7, 2});
                trial.ball = ballAt(dist, az);
                const double v = visibleShare(trial);
                if ((v >= 0.55 && v <= 0.85) || side > 0.59) {
                    s.robots = trial.robots;
                    break;
                }
            }
        } else {
            // Touching our own body.
            dist = 0.24 + 0.11 + 0.01;
        }
        break;
    }
    }
    if (!(cell.distractors == OpticsDistractors::RobotsFeetShadow && situation == 1)) s.ball = ballAt(dist, az);
    keepBallOnCarpet(s, renderer.field());
    return s;
}

OpticsCellFrames renderCell(const OpticsCell& cell, const Config& base)
{
    const OpticsCamera cam = opticsCellCamera(cell, base);
    OpticsCellFrames out;
    out.fittedConfig = cam.calibration->ok() ? cam.calibration->config : base;
    out.calibrationError = cam.calibration->error.value_or("");
    out.field = cam.renderer->field().dimensions();
    out.ballRadiusM = OpticsScene{}.ballRadius;  // opticsCellScene keeps the default ball
    for (int i = 0; i < cell.frames; ++i) {
        const OpticsScene scene = opticsCellScene(cell, i, *cam.renderer);
        OpticsTruth t;
        out.frames.push_back(cam.renderer->render(scene, &t));
        out.truth[i] = toTruthRow(t, i, cell.ballPresent);
        if (cell.ballPresent && !out.truth[i].ballVisible && t.visibleFraction > 0.0)  // some of it shows
            out.hiddenBalls[i] = cv::Point2d(t.xM, t.yM);
    }
    return out;
}

TruthRow toTruthRow(const OpticsTruth& t, int frame, bool ballPresent)
{
    TruthRow row;
    row.frame = frame;
    row.robot = t.pose;
    row.ballVisible = ballPresent && t.ballVisible;
    if (row.ballVisible) {
        row.px = t.px;
        row.py = t.py;
        row.radiusPx = t.radiusPx;
        row.xM = t.xM;
        row.yM = t.yM;
    }
    return row;
}

}  // namespace omnitune
