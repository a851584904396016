#include "calib/sim/optics/CatadioptricCamera.h"

#include "core/Pi.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace omnitune {

namespace {

// Where the camera ray with horizontal/vertical ratio `tanTheta` meets the mirror: the radius r
// with r / tanTheta = vertex + h(r). Returns a negative value when it passes beyond the rim.
double mirrorHitRadius(const MirrorProfile& mirror, double vertex, double tanTheta)
{
    const double rim = mirror.rimRadius();
    auto f = [&](double r) { return r - tanTheta * (vertex + mirror.height(r)); };
    if (f(rim) < 0) return -1.0;  // still below the mirror surface at the rim: misses it
    // f rises and is concave (the mirror curves up), and f(tan * vertex) <= 0: Newton from there
    // approaches the root from the left without overshooting.
    double r = std::min(tanTheta * vertex, rim);
    for (int i = 0; i < 12; ++i) {
        const double step = f(r) / std::max(1.0 - tanTheta * mirror.slope(r), 1e-6);
        r = std::clamp(r - step, 0.0, rim);
        if (std::abs(step) < 1e-10) break;
    }
    return r;
}

cv::Vec3d reflect(const cv::Vec3d& d, const cv::Vec3d& n) { return d - 2.0 * d.dot(n) * n; }

// Mirror normal at the surface point at horizontal (x, y).
cv::Vec3d mirrorNormal(const MirrorProfile& mirror, double x, double y)
{
    const double r = std::hypot(x, y);
    if (r < 1e-12) return {0, 0, 1};
    const double s = mirror.slope(r);
    return cv::normalize(cv::Vec3d(-s * x / r, -s * y / r, 1.0));
}

// Height above the camera where the reflected rays of camera rays that hit the mirror at radii
// rLo..rHi cross the axis, averaged: a tape-measure figure for the effective viewpoint.
double meanAxisCrossing(const MirrorProfile& mirror, double vertex, double rLo, double rHi)
{
    double sum = 0;
    int n = 0;
    for (double r = rLo; r <= rHi + 1e-12; r += (rHi - rLo) / 8) {
        const double z = vertex + mirror.height(r);
        const cv::Vec3d d = cv::normalize(cv::Vec3d(r, 0, z));
        const cv::Vec3d o = reflect(d, mirrorNormal(mirror, r, 0));
        sum += z - r * o[2] / o[0];
        ++n;
    }
    return sum / n;
}

// Segment-segment closest distance (P0 + s u, s in [0,1]; Q0 + t v, t in [0,1]).
double segmentDistance(const cv::Vec3d& p0, const cv::Vec3d& u, const cv::Vec3d& q0, const cv::Vec3d& v)
{
    const cv::Vec3d w = p0 - q0;
    const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
    const double den = a * c - b * b;
    double s = den > 1e-18 ? std::clamp((b * e - c * d) / den, 0.0, 1.0) : 0.0;
    double t = c > 1e-18 ? std::clamp((b * s + e) / c, 0.0, 1.0) : 0.0;
    s = a > 1e-18 ? std::clamp((b * t - d) / a, 0.0, 1.0) : 0.0;
    return cv::norm(w + s * u - t * v);
}

// Rods that cross the outer part of the image: each runs inside the camera's view cone from the
// mirror (where camera rays of tan ~0.28..0.33 meet it) outwards and down past the cone.
std::vector<SupportRod> makeRods(const MirrorProfile& mirror, double cameraHeight, double vertex, int count,
                                 double firstAzimuth)
{
    std::vector<SupportRod> rods;
    for (int k = 0; k < count; ++k) {
        const double az = firstAzimuth + 2 * kPi * k / count + 0.15 * std::sin(3.1 * k + 1);
        const double tanIn = 0.28 + 0.05 * (0.5 + 0.5 * std::sin(1.7 * k + 0.3));
        const double rTop = mirrorHitRadius(mirror, vertex, tanIn);
        const double zTop = cameraHeight + vertex + mirror.height(rTop) - 0.001;
        const double azBottom = az + (k % 2 ? 0.12 : -0.09);
        const double rBottom = mirror.rimRadius() * 1.15;
        SupportRod rod;
        rod.top = {rTop * std::cos(az), rTop * std::sin(az), zTop};
        rod.bottom = {rBottom * std::cos(azBottom), rBottom * std::sin(azBottom), cameraHeight + 0.035};
        rod.radius = 0.0010 + 0.0002 * (k % 3);
        rods.push_back(rod);
    }
    return rods;
}

}  // namespace

CatadioptricCameraParams hyperbolicCameraParams(cv::Size image, int rods)
{
    CatadioptricCameraParams p;
    p.image = image;
    auto mirror = std::make_shared<HyperbolicMirror>(0.030, 0.040, 0.045);
    const double e = mirror->eccentricDistance();
    p.mirror = mirror;
    p.vertexAboveCamera = e + mirror->a();           // the pinhole sits at the other sheet's focus
    p.cameraHeight = 0.75 - 2 * e;                    // viewpoint (the mirror's focus) at 0.75 m
    p.measuredViewpointHeight = p.cameraHeight + 2 * e;
    const bool square = image.width == image.height;
    p.focalPx = square ? 478.0 : 492.0;               // rim at ~228 / ~235 px
    p.principal = square ? cv::Point2d(238.6, 242.3) : cv::Point2d(323.7, 237.9);
    p.tiltX = 0.006;
    p.tiltY = -0.004;
    p.rods = makeRods(*mirror, p.cameraHeight, p.vertexAboveCamera, rods, 0.6);
    p.name = "hyperbolic-" + std::to_string(image.width) + "x" + std::to_string(image.height) + "-rods" +
             std::to_string(rods);
    return p;
}

CatadioptricCameraParams sphericalCameraParams(cv::Size image, int rods)
{
    CatadioptricCameraParams p;
    p.image = image;
    auto mirror = std::make_shared<SphericalMirror>(0.090, 0.044);
    p.mirror = mirror;
    p.vertexAboveCamera = 0.08;
    p.cameraHeight = 0.62;
    // The team measures where rays towards the near field (~1..3 m) cross the axis, to the cm.
    const double crossing = meanAxisCrossing(*mirror, p.vertexAboveCamera, 0.02, 0.04);
    p.measuredViewpointHeight = std::round((p.cameraHeight + crossing) * 100.0) / 100.0;
    const bool square = image.width == image.height;
    p.focalPx = square ? 470.0 : 482.0;
    p.principal = square ? cv::Point2d(241.4, 237.2) : cv::Point2d(317.2, 242.6);
    p.tiltX = -0.005;
    p.tiltY = 0.007;
    p.rods = makeRods(*mirror, p.cameraHeight, p.vertexAboveCamera, rods, 2.2);
    p.name = "spherical-" + std::to_string(image.width) + "x" + std::to_string(image.height) + "-rods" +
             std::to_string(rods);
    return p;
}

CatadioptricCamera::CatadioptricCamera(const CatadioptricCameraParams& params, int marginPx)
    : params_(params), margin_(std::max(marginPx, 0))
{
    if (!params_.mirror) throw std::invalid_argument("CatadioptricCamera: no mirror");
    if (params_.image.width < 16 || params_.image.height < 16 || !(params_.focalPx > 0))
        throw std::invalid_argument("CatadioptricCamera: bad image size or focal length");
    const MirrorProfile& mirror = *params_.mirror;
    stride_ = params_.image.width + 2 * margin_;
    rows_ = params_.image.height + 2 * margin_;
    const std::size_t n = std::size_t(stride_) * std::size_t(rows_);
    kinds_.assign(n, PixelKind::Housing);
    origins_.assign(n, cv::Vec3f(0, 0, 0));
    directions_.assign(n, cv::Vec3f(0, 0, 0));

    // Camera to robot: image +x is robot +x, image +y is robot -y, the optical axis up; then tilted.
    const double cx = std::cos(params_.tiltX), sx = std::sin(params_.tiltX);
    const double cy = std::cos(params_.tiltY), sy = std::sin(params_.tiltY);
    const cv::Matx33d rx(1, 0, 0, 0, cx, -sx, 0, sx, cx);
    const cv::Matx33d ry(cy, 0, sy, 0, 1, 0, -sy, 0, cy);
    const cv::Matx33d tilt = ry * rx;
    const double vertex = params_.vertexAboveCamera;
    const double zCam = params_.cameraHeight;

    double rimSumX = 0, rimSumY = 0, rimSumR = 0;
    int rimCount = 0;
    for (int y = -margin_; y < params_.image.height + margin_; ++y) {
        for (int x = -margin_; x < params_.image.width + margin_; ++x) {
            const std::size_t i = std::size_t(index(x, y));
            const cv::Vec3d d = cv::normalize(cv::Vec3d(tilt * cv::Vec3d((x - params_.principal.x) / params_.focalPx,
                                                                         -(y - params_.principal.y) / params_.focalPx, 1.0)));
            if (d[2] <= 1e-6) continue;
            const double sxy = std::hypot(d[0], d[1]);
            const double r = mirrorHitRadius(mirror, vertex, sxy / d[2]);
            if (r < 0) continue;
            const double t = (vertex + mirror.height(r)) / d[2];
            const cv::Vec3d hit = t * d;  // relative to the pinhole
            const cv::Vec3d out = cv::normalize(reflect(d, mirrorNormal(mirror, hit[0], hit[1])));
            const cv::Vec3d origin(hit[0], hit[1], hit[2] + zCam);
            origins_[i] = cv::Vec3f(origin);
            directions_[i] = cv::Vec3f(out);
            PixelKind kind = PixelKind::World;
            for (const SupportRod& rod : params_.rods) {
                const cv::Vec3d b(rod.bottom.x, rod.bottom.y, rod.bottom.z - zCam);
                const cv::Vec3d tp(rod.top.x, rod.top.y, rod.top.z - zCam);
                if (segmentDistance(cv::Vec3d(0, 0, 0), hit, b, tp - b) < rod.radius) kind = PixelKind::Rod;
            }
            if (kind == PixelKind::World && out[2] < 0) {
                // Down past the mast (the camera itself) or onto the robot's top plate.
                const double tm = (origin[2] - zCam) / -out[2];
                const double mx = origin[0] + tm * out[0], my = origin[1] + tm * out[1];
                const double tb = (origin[2] - params_.bodyTop) / -out[2];
                const double bx = origin[0] + tb * out[0], by = origin[1] + tb * out[1];
                if (std::hypot(mx, my) < params_.mastRadius) kind = PixelKind::Mast;
                else if (std::hypot(bx, by) < params_.bodyRadius) kind = PixelKind::Body;
            }
            kinds_[i] = kind;
            if (r > 0.995 * mirror.rimRadius()) {
                rimSumX += x, rimSumY += y, ++rimCount;
            }
        }
    }
    if (rimCount > 0) rimCentre_ = {rimSumX / rimCount, rimSumY / rimCount};
    for (int y = -margin_; y < params_.image.height + margin_; ++y)
        for (int x = -margin_; x < params_.image.width + margin_; ++x) {
            const std::size_t i = std::size_t(index(x, y));
            if (kinds_[i] == PixelKind::Housing) continue;
            const cv::Vec3f& o = origins_[i];
            if (std::hypot(o[0], o[1]) > 0.995 * mirror.rimRadius()) rimSumR += std::hypot(x - rimCentre_.x, y - rimCentre_.y);
        }
    if (rimCount > 0) rimRadiusPx_ = rimSumR / rimCount + 0.5;
}

bool CatadioptricCamera::inTable(int x, int y) const
{
    return x >= -margin_ && y >= -margin_ && x < params_.image.width + margin_ && y < params_.image.height + margin_;
}

WorldRay CatadioptricCamera::ray(int x, int y) const
{
    const std::size_t i = std::size_t(index(x, y));
    return {cv::Vec3d(origins_[i]), cv::Vec3d(directions_[i])};
}

std::optional<WorldRay> CatadioptricCamera::rayAt(double x, double y) const
{
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    if (!inTable(x0, y0) || !inTable(x0 + 1, y0 + 1)) return std::nullopt;
    const double fx = x - x0, fy = y - y0;
    WorldRay out{cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0)};
    const int dxs[4] = {0, 1, 0, 1}, dys[4] = {0, 0, 1, 1};
    const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    for (int k = 0; k < 4; ++k) {
        const std::size_t i = std::size_t(index(x0 + dxs[k], y0 + dys[k]));
        if (kinds_[i] == PixelKind::Housing) return std::nullopt;
        out.origin += w[k] * cv::Vec3d(origins_[i]);
        out.direction += w[k] * cv::Vec3d(directions_[i]);
    }
    out.direction = cv::normalize(out.direction);
    return out;
}

std::optional<cv::Point2d> CatadioptricCamera::project(const cv::Point3d& q, std::optional<cv::Point2d> hint) const
{
    if (hint) {
        if (auto p = refine(q, *hint)) return p;
    }
    // Coarse: every 3rd pixel of the table.
    double best = std::numeric_limits<double>::max();
    cv::Point2d p(0, 0);
    for (int y = -margin_; y < params_.image.height + margin_ - 1; y += 3)
        for (int x = -margin_; x < params_.image.width + margin_ - 1; x += 3) {
            const std::size_t i = std::size_t(index(x, y));
            if (kinds_[i] == PixelKind::Housing) continue;
            const cv::Vec3f& o = origins_[i];
            const cv::Vec3f& d = directions_[i];
            if (d[2] > -1e-6 || o[2] <= q.z) continue;
            const double t = (q.z - o[2]) / d[2];
            const double ex = o[0] + t * d[0] - q.x, ey = o[1] + t * d[1] - q.y;
            const double e2 = ex * ex + ey * ey;
            if (e2 < best) best = e2, p = {double(x), double(y)};
        }
    if (best == std::numeric_limits<double>::max()) return std::nullopt;
    return refine(q, p);
}

std::optional<cv::Point2d> CatadioptricCamera::refine(const cv::Point3d& q, cv::Point2d p) const
{
    // The ray's point at the target's height, or nullopt when it does not come down to it.
    auto at = [&](double x, double y) -> std::optional<cv::Point2d> {
        const auto r = rayAt(x, y);
        if (!r || r->direction[2] > -1e-6 || r->origin[2] <= q.z) return std::nullopt;
        const double t = (q.z - r->origin[2]) / r->direction[2];
        return cv::Point2d(r->origin[0] + t * r->direction[0], r->origin[1] + t * r->direction[1]);
    };
    // Gauss-Newton on the bilinear ray field.
    for (int it = 0; it < 16; ++it) {
        const auto g = at(p.x, p.y), gx = at(p.x + 0.25, p.y), gy = at(p.x, p.y + 0.25);
        if (!g || !gx || !gy) break;
        const cv::Matx22d j((gx->x - g->x) / 0.25, (gy->x - g->x) / 0.25, (gx->y - g->y) / 0.25, (gy->y - g->y) / 0.25);
        const cv::Vec2d err(g->x - q.x, g->y - q.y);
        bool ok = false;
        const cv::Matx22d inv = j.inv(cv::DECOMP_LU, &ok);
        if (!ok) break;
        cv::Vec2d step = inv * err;
        const double len = cv::norm(step);
        if (len > 4) step *= 4 / len;
        p.x -= step[0], p.y -= step[1];
        if (len < 1e-4) break;
    }
    const auto g = at(p.x, p.y);
    if (!g || std::hypot(g->x - q.x, g->y - q.y) > 0.02) return std::nullopt;
    return p;
}

}  // namespace omnitune
