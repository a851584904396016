#include "calib/sim/Tour.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnitune {

namespace {

// Waypoints relative to the ball, counter-clockwise around it, 1.1..2.9 m away; point 1 is
// where the thesis' robot started (the centre spot, for the thesis' ball spot).
constexpr std::array<std::array<double, 2>, 5> kWaypointOffsets = {
    {{0.05, -2.0}, {1.3, -0.6}, {2.2, 1.9}, {-0.7, 0.8}, {-2.6, -1.2}}};

// Obstacles stand outside the loop, so they are behind the robot rather than between it and
// the ball; the person stands in the gap between two of them.
constexpr double kObstacleDistance = 4.0;  // m from the ball
constexpr std::array<double, 3> kObstacleAngles = {60.0, 190.0, 310.0};  // deg, field frame
constexpr std::array<int, 3> kObstacleTeams = {1, 2, 0};
constexpr double kObstacleJitter = 0.25;   // m
constexpr double kFeetDistance = 3.0;      // m from the ball
constexpr double kFeetAngle = 125.0;       // deg
constexpr int kSamplesPerLeg = 400;        // dense polyline for arc-length spacing

cv::Point2d catmullRom(const cv::Point2d& p0, const cv::Point2d& p1, const cv::Point2d& p2,
                       const cv::Point2d& p3, double t)
{
    const double t2 = t * t, t3 = t2 * t;
    return 0.5 * ((2 * p1) + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 + (3 * p1 - p0 - 3 * p2 + p3) * t3);
}

double wrapAngle(double a) { return std::remainder(a, 2 * M_PI); }

}  // namespace

std::array<cv::Point2d, 5> tourWaypoints(const TourOptions& o)
{
    std::array<cv::Point2d, 5> w;
    for (std::size_t i = 0; i < w.size(); ++i)
        w[i] = {o.ballX + kWaypointOffsets[i][0], o.ballY + kWaypointOffsets[i][1]};
    return w;
}

std::vector<SceneOptions> makeTour(const TourOptions& o)
{
    if (o.frames < 1) throw std::invalid_argument("tour: frames must be at least 1");
    const std::array<cv::Point2d, 5> wp = tourWaypoints(o);
    const cv::Point2d ball(o.ballX, o.ballY);

    // A smooth closed curve through the waypoints, then equal arc-length steps along it.
    std::vector<cv::Point2d> path;
    const int n = int(wp.size());
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < kSamplesPerLeg; ++k)
            path.push_back(catmullRom(wp[std::size_t((i + n - 1) % n)], wp[std::size_t(i)], wp[std::size_t((i + 1) % n)],
                                      wp[std::size_t((i + 2) % n)], double(k) / kSamplesPerLeg));
    path.push_back(path.front());
    std::vector<double> length(path.size(), 0.0);
    for (std::size_t i = 1; i < path.size(); ++i) length[i] = length[i - 1] + cv::norm(path[i] - path[i - 1]);
    const double total = length.back();

    // Everything chosen from the seed is chosen once, so the scene stays put along the tour.
    cv::RNG pick(0x70a0000ull + o.seed);
    std::vector<ObstacleRobot> obstacles;
    for (std::size_t i = 0; i < kObstacleAngles.size(); ++i) {
        const double a = kObstacleAngles[i] * M_PI / 180;
        ObstacleRobot r;
        r.x = ball.x + kObstacleDistance * std::cos(a) + pick.uniform(-kObstacleJitter, kObstacleJitter);
        r.y = ball.y + kObstacleDistance * std::sin(a) + pick.uniform(-kObstacleJitter, kObstacleJitter);
        r.team = kObstacleTeams[i];
        obstacles.push_back(r);
    }
    const double feetA = kFeetAngle * M_PI / 180 + pick.uniform(-0.2, 0.2);
    const cv::Point2d feet = ball + kFeetDistance * cv::Point2d(std::cos(feetA), std::sin(feetA));
    const double shadowA = pick.uniform(0.0, 2 * M_PI);
    const double shadowD = pick.uniform(0.5, 0.7);  // clear of the ball, which stays >= ~1.05 m away
    const double spin = pick.uniform(0.0, 2 * M_PI);

    std::vector<SceneOptions> frames;
    frames.reserve(std::size_t(o.frames));
    for (int f = 0; f < o.frames; ++f) {
        const double s = total * f / o.frames;
        const std::size_t i = std::size_t(std::upper_bound(length.begin(), length.end(), s) - length.begin()) - 1;
        const std::size_t j = std::min(i + 1, path.size() - 1);
        const double seg = length[j] - length[i];
        const double u = seg > 0 ? (s - length[i]) / seg : 0.0;
        const cv::Point2d at = path[i] + u * (path[j] - path[i]);
        // Facing the ball at waypoint 1, then turning steadily relative to it, so the ball sweeps
        // spinTurns times through every image direction while its distance changes.
        const cv::Point2d toBall = ball - at;
        const double heading = std::atan2(toBall.y, toBall.x) - 2 * M_PI * o.spinTurns * s / total;

        SceneOptions sc;
        sc.robot = {at.x, at.y, wrapAngle(heading)};
        sc.ballPresent = true;
        sc.ballX = ball.x;
        sc.ballY = ball.y;
        sc.ball = o.ball;
        sc.ballSpin = spin;
        if (o.obstacles) sc.obstacles = obstacles;
        sc.lightLevel = o.lightLevel;
        sc.lightGradient = o.lightGradient;
        sc.noiseSigma = o.noiseSigma;
        sc.humanFeet = o.feet;
        sc.feetAt = feet;
        sc.headShadow = o.shadow;
        sc.shadowOffset = cv::Point2d(shadowD * std::cos(shadowA), shadowD * std::sin(shadowA));
        sc.seed = o.seed * 100003u + unsigned(f);
        frames.push_back(sc);
    }
    return frames;
}

}  // namespace omnitune
