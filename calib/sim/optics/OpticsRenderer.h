#pragma once
// Renders OpticsScene frames through a CatadioptricCamera by intersecting each pixel's
// precomputed world ray with the scene: floor (carpet, the MSL field's white lines from
// FieldModel, the hall floor and walls beyond), the ball sphere (panels from BallKind, Lambert
// light, its contact shadow), other robots, a person's feet, the head's shadow. Where the ball
// appears and how big it looks come only from the optics: nothing of the detector's BallModel,
// DistanceMap or Config geometry is used.
#include "calib/sim/FieldModel.h"
#include "calib/sim/optics/CatadioptricCamera.h"
#include "calib/sim/optics/OpticsScene.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

class OpticsRenderer {
public:
    // Keeps a reference to `camera`, which must outlive the renderer. Precomputes the static
    // background (housing, rods, the robot's body) and the field's line distances (~0.1 s).
    explicit OpticsRenderer(const CatadioptricCamera& camera, const FieldDimensions& field = {});

    // CV_8UC3 BGR frame of the camera's image size. Same scene (and seed), same bytes.
    // Thread-safe (no mutable state).
    cv::Mat render(const OpticsScene& scene, OpticsTruth* truth = nullptr) const;

    // The ball's silhouette only (no rendering): what render() reports as truth.
    OpticsTruth ballTruth(const OpticsScene& scene) const;

    const CatadioptricCamera& camera() const { return camera_; }
    const FieldModel& field() const { return field_; }

private:
    struct WorldPixel {
        int offset = 0;          // y * width + x in the frame
        int x = 0, y = 0;
        float gx = 0, gy = 0;    // robot-frame floor point of the ray (m); valid when hitsFloor
        float footprint = 0;     // m of floor one pixel spans there
        float azimuth = 0;       // rad, of the ray's horizontal direction
        float vignette = 1;      // uneven light: the rim is darker
        bool hitsFloor = false;
    };
    struct Frame;
    struct Cylinder;

    void buildObjects(const OpticsScene& scene, Frame& frame) const;
    cv::Vec3f floorColour(const OpticsScene& scene, const Frame& frame, double gx, double gy, double footprint) const;
    float lightAt(const OpticsScene& scene, const Frame& frame, double fx, double fy, float vignette) const;
    // Nearest object hit along a ray: t (m) and its lit colour; t = inf when none.
    double hitObjects(const Frame& frame, const WorldRay& ray, float azimuth, cv::Vec3f& colour) const;
    // `image` (CV_32FC3) and `coverage` (CV_32FC1, the ball's unhidden share per pixel) may be null.
    void drawBall(const OpticsScene& scene, const Frame& frame, cv::Mat* image, cv::Mat* coverage,
                  OpticsTruth& truth) const;

    const CatadioptricCamera& camera_;
    FieldModel field_;
    cv::Mat background_;             // CV_32FC3: housing, rods, mast, body (body and rods lit)
    cv::Mat backgroundLit_;          // CV_8UC1: 1 where the background takes the hall's light
    std::vector<WorldPixel> world_;  // pixels that see the world
    cv::Mat lineGrid_;               // CV_32FC1, m to the nearest line centre, every kLineStep m
    cv::Mat carpetGrid_;             // CV_32FC1, carpet brightness factor every 0.1 m
    cv::Point2d gridOrigin_;
    cv::Rect2d carpet_;
    cv::Mat noise_;                  // CV_32FC3 unit Gaussian noise, a little larger than a frame
};

}  // namespace omnitune
