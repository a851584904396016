#pragma once
// Renders what the omnidirectional camera sees on an MSL field, with the ball's ground truth, so
// the detector can be tested and tuned without a robot. Each pixel looks along its image
// direction to the ground distance the config's distance map gives for its image radius; the
// ball is a disc at DistanceMap::ballPixels() with BallModel::radiusAt() as radius. So a
// perfect detector run with the same Config recovers the truth exactly; the simulator never
// contradicts the calibration it is given.
//
// Coordinates (see RobotPose.h): the image is the robot frame seen from above, forward (the
// heading) up, the robot's right to image +x. GroundTruth::xM/yM and the pipeline's
// BallDetection::xM/yM are both robot-frame metres (x along image +x, y along image -y).
#include "calib/sim/BallKind.h"
#include "core/Config.h"
#include "calib/sim/FieldModel.h"
#include "calib/sim/RobotPose.h"

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace omnitune {

// Another robot standing on the field: a black cylinder, optionally with a team marker band.
struct ObstacleRobot {
    double x = 0.0;        // m, field frame
    double y = 0.0;        // m
    double radius = 0.25;  // m
    double height = 0.8;   // m; above the viewpoint it hides the ground behind it out to the rim
    int team = 0;          // 0 no marker, 1 cyan marker band, 2 magenta marker band
};

struct SceneOptions {
    RobotPose robot;                 // our robot, carrying the camera
    bool ballPresent = true;
    double ballX = 0.0;              // m, field frame, ball centre over the ground
    double ballY = 2.0;              // m
    BallKind ball = BallKind::Orange;
    double ballSpin = 0.0;           // rad, rotation of the ball's panels about the vertical
    std::vector<ObstacleRobot> obstacles;
    double lightLevel = 1.0;         // global brightness factor; below ~0.43 the carpet falls into
                                     // the default LUT's black class (V <= 60)
    double lightGradient = 0.0;      // 0..1: vignetting towards the mirror rim plus a light side
                                     // of the hall (field +y brighter); 1 darkens the rim by ~1/3
    double noiseSigma = 2.0;         // Gaussian sensor noise per channel, grey levels
    double opticalBlurPx = 0.5;      // Gaussian lens blur sigma over the whole frame, px (0 = sharp)
    double motionBlurPx = 0.0;       // ball motion blur length, px (0 = none)
    double motionAngle = 0.0;        // rad, image direction of that motion (from +x, y up)
    double occlusion = 0.0;          // 0..1 share of the ball disc hidden by a black robot edge
                                     // that comes in from the counter-clockwise side
    bool humanFeet = false;          // two dark shoes with jeans legs standing on the field
    std::optional<cv::Point2d> feetAt;  // m, field frame, between the shoes; unset: chosen from
                                        // `seed`, 1.2..2.2 m from the robot
    bool headShadow = false;         // the robot head's roundish shadow on the carpet
    std::optional<cv::Point2d> shadowOffset;  // m, field-frame offset from the robot; unset:
                                              // chosen from `seed`, 0.55..1.0 m away
    unsigned seed = 1;               // sensor noise and unset distractor spots; same seed, same bytes
};

struct GroundTruth {
    bool ballVisible = false;     // ball present, centre in the image, >= half of its disc unhidden
    double px = 0.0;              // ball centre in the image, px (pixel centres at integers)
    double py = 0.0;
    double radiusPx = 0.0;        // BallModel::radiusAt(distancePx)
    double distancePx = 0.0;      // DistanceMap::ballPixels(distanceM)
    double xM = 0.0;              // m, robot frame (x along image +x, y along image -y)
    double yM = 0.0;
    double distanceM = 0.0;       // horizontal, robot centre to ball centre
    double visibleFraction = 0.0; // 0..1 of the disc not hidden (robot body, rim, mask, obstacles, occluder)
    RobotPose pose;               // the robot's pose in this frame
};

class SceneSimulator {
public:
    // Uses config.geometry (size, centre, radii), config.mask, config.distanceMap and
    // config.ball. Throws std::invalid_argument for a mask of the wrong size or a bad distance
    // map or field. Precomputes every pixel's ground direction and the field's line distances
    // (~30 ms), so a 640x480 frame renders in ~15-20 ms.
    explicit SceneSimulator(const Config& config, const FieldDimensions& field = {});

    // CV_8UC3 BGR frame of geometry.imageWidth x imageHeight. Thread-safe (no mutable state).
    cv::Mat render(const SceneOptions& scene, GroundTruth* truth = nullptr) const;

    // Where the ball of `scene` is seen, without rendering (visibleFraction ignores obstacles,
    // the occluder and the mask: it only counts the disc part inside the processed ring).
    GroundTruth groundTruth(const SceneOptions& scene) const;

    const FieldModel& field() const { return field_; }

private:
    struct RingPixel {
        int offset = 0;          // y * width + x
        float cosA = 0, sinA = 0; // image direction in the robot frame (y up)
        float ground = 0;        // m, DistanceMap::toGround(rho)
        float footprint = 0;     // m of ground one pixel spans here (antialiasing width)
        float rho = 0;           // px from the image centre
    };

    struct Frame;
    void placeThings(Frame& frame) const;  // distractors, robots and goals of this scene
    void shadeWorld(Frame& frame) const;   // every ring pixel: ground, standing things, light
    void drawBall(Frame& frame, GroundTruth& truth) const;  // ball, occluder; sets visibleFraction

    double lineDistance(double fx, double fy) const;
    double carpetShade(double fx, double fy) const;

    GeometryOptions geometry_;
    DistanceMap distanceMap_;
    BallModel ballModel_;
    cv::Mat mask_;
    FieldModel field_;
    double bodyRadius_ = 0;    // px; the robot's own body is seen inside
    double mirrorRadius_ = 0;  // px; the mirror's rim; beyond it the camera housing
    double maxGround_ = 0;     // m, farthest ground any ring pixel sees

    std::vector<RingPixel> ring_;   // pixels that see the world (between body and rim)
    cv::Mat ringIndex_;             // CV_32SC1 index into ring_, -1 elsewhere
    cv::Mat background_;            // CV_32FC3: housing, robot body and mask structure

    cv::Mat lineGrid_;              // CV_32FC1 distance to the nearest line, m, over the carpet
    cv::Mat carpetGrid_;            // CV_32FC1 carpet brightness factor, coarser
    cv::Point2d gridOrigin_;        // field m of both grids' first texel centre
};

}  // namespace omnitune
