#pragma once
// Image distance from the robot centre (px) <-> ground distance (m), from calibration points,
// with the ball-height correction the thesis applies to the final position (ch. 4.3).
#include <vector>

namespace omnitune {

struct DistanceMapOptions {
    // Calibration points: image radius (px, strictly increasing) and the ground distance it
    // sees (m, strictly increasing). Interpolated by a monotone cubic (Fritsch-Carlson).
    std::vector<double> pixelRadii = {0, 50, 70, 105, 140, 170, 205, 240};
    std::vector<double> groundDistances = {0.0, 0.30, 0.45, 0.85, 1.45, 2.20, 3.60, 6.50};
    double viewpointHeight = 0.75;  // m above the ground of the mirror's effective viewpoint
    double ballRadius = 0.11;       // m (FIFA size 5); the ball centre is this high
};

class DistanceMap {
public:
    DistanceMap() = default;
    // `options` must have passed checkConfig() (the one place user values are checked).
    explicit DistanceMap(const DistanceMapOptions& options);

    // Ground distance (m) of the point seen at image radius `px`. Beyond the last point the
    // last segment's slope is continued.
    double toGround(double px) const;
    // Inverse of toGround (px for a ground distance in m).
    double toPixels(double metres) const;
    // Horizontal distance (m) of a ball whose centre is seen at image radius `px`: the ray
    // through the ball centre meets the ground behind the ball, so scale by (H - r) / H.
    double ballDistance(double px) const;
    // Image radius (px) at which a ball whose centre lies `metres` away is seen.
    double ballPixels(double metres) const;

    const DistanceMapOptions& options() const { return options_; }

private:
    DistanceMapOptions options_;
    std::vector<double> slopes_;  // Hermite tangents at the points
};

}  // namespace omnitune
