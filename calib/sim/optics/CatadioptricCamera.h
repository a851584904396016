#pragma once
// A catadioptric camera as MSL robots carry it: a pinhole camera on the robot's mast looking up
// at a mirror of revolution (MirrorProfile) whose axis is the robot's vertical axis. Every pixel's
// camera ray is traced once to the mirror and reflected, so rendering a frame only intersects
// precomputed world rays with the scene. Rays that miss the mirror see the dark housing; rays
// blocked by a mirror-support rod before the mirror see the rod; reflected rays that come down
// onto the robot's own top see the body.
//
// Robot frame (calib/sim/RobotPose.h): x the robot's right, y its forward, z up, floor at z = 0.
// The image shows that frame seen from above: robot +x is image +x, robot +y is image -y (the
// camera's image is flipped so, like every MSL team sets it).
#include "calib/sim/optics/MirrorProfile.h"

#include <opencv2/core.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

// A thin bar holding the mirror: from the camera's mount plate up to the mirror's rim.
struct SupportRod {
    cv::Point3d bottom;    // m, robot frame
    cv::Point3d top;       // m
    double radius = 0.004; // m
};

struct CatadioptricCameraParams {
    cv::Size image{640, 480};
    double focalPx = 480.0;
    cv::Point2d principal{320.0, 240.0};  // px; need not be the image centre
    double tiltX = 0.0;                   // rad, the optical axis' tilt about the robot's x axis
    double tiltY = 0.0;                   // rad, about y
    double cameraHeight = 0.55;           // m, pinhole above the floor
    double vertexAboveCamera = 0.1;       // m, mirror vertex above the pinhole
    std::shared_ptr<const MirrorProfile> mirror;
    double bodyRadius = 0.24;             // m, the robot's top plate, seen in the middle
    double bodyTop = 0.30;                // m above the floor
    double mastRadius = 0.022;            // m, the camera and its mast (seen at the very centre)
    std::vector<SupportRod> rods;
    // What a team measures with a tape: the height of the mirror's effective viewpoint (for a
    // hyperbolic mirror its focus; for another profile where the reflected rays cross the axis).
    double measuredViewpointHeight = 0.75;
    std::string name;
};

// The two cameras of the simulator, sized so the mirror image is a circle of ~230 px radius
// that sees the floor out to ~7 m at its rim. `rods`: 0 (a clear cylinder holds the mirror) or
// 2..6 support rods.
CatadioptricCameraParams hyperbolicCameraParams(cv::Size image, int rods = 0);
CatadioptricCameraParams sphericalCameraParams(cv::Size image, int rods = 0);

// A world ray: origin on the mirror, unit direction, robot frame.
struct WorldRay {
    cv::Vec3d origin;
    cv::Vec3d direction;
};

class CatadioptricCamera {
public:
    enum class PixelKind : std::uint8_t { Housing, Rod, Body, Mast, World };

    // Traces every pixel of the image plus `marginPx` around it (so a ball cut by the frame's
    // border still has its whole silhouette). ~0.1 s; throws std::invalid_argument on a missing mirror.
    explicit CatadioptricCamera(const CatadioptricCameraParams& params, int marginPx = 24);

    const CatadioptricCameraParams& params() const { return params_; }
    cv::Size imageSize() const { return params_.image; }
    int margin() const { return margin_; }

    // Frame pixel (x, y), may lie in the margin: -margin <= x < width + margin.
    bool inTable(int x, int y) const;
    PixelKind kind(int x, int y) const { return kinds_[index(x, y)]; }
    // The reflected ray of the pixel's centre (also for Rod pixels: what the rod hides).
    WorldRay ray(int x, int y) const;
    // Between pixel centres, bilinear in origin and direction; nullopt when a neighbour misses the mirror.
    std::optional<WorldRay> rayAt(double x, double y) const;

    // Where a world point is seen: the sub-pixel position whose reflected ray passes through it
    // (frame px, may lie in the margin). nullopt when no ray of the table comes within 2 cm.
    std::optional<cv::Point2d> project(const cv::Point3d& point) const;

    // Where the mirror's rim is seen (px, the mean over its circle) and its mean radius: what a
    // rim fit should find.
    cv::Point2d rimCentre() const { return rimCentre_; }
    double rimRadiusPx() const { return rimRadiusPx_; }

private:
    int index(int x, int y) const { return (y + margin_) * stride_ + (x + margin_); }

    CatadioptricCameraParams params_;
    int margin_ = 0;
    int stride_ = 0;
    int rows_ = 0;
    std::vector<PixelKind> kinds_;
    std::vector<cv::Vec3f> origins_;
    std::vector<cv::Vec3f> directions_;
    cv::Point2d rimCentre_;
    double rimRadiusPx_ = 0.0;
};

}  // namespace omnitune
