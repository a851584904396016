#pragma once
// Radial sensors (thesis Fig. 4.3): rays from the robot centre between two radii. Line and
// obstacle detection read the runs of colour classes along each ray instead of the whole image.
#include "core/ColorClass.h"
#include "core/Geometry.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

struct RadialSensorOptions {
    int count = 90;             // rays, evenly spaced over 360 degrees, 1..720
    double innerRadius = 50.0;  // px from the centre where a ray starts
    double outerRadius = 240.0; // px where it ends
    double angleOffsetDeg = 0.0;  // direction of ray 0, degrees counter-clockwise from image +x, 0..360
};

// Direction of `ray` (radians, 0 = +x, counter-clockwise in the image): the offset, then
// evenly spaced. The robot's sensors and the window's overlay both use this.
double radialSensorAngle(const RadialSensorOptions& options, int ray);

struct SensorPixel {
    int x = 0;
    int y = 0;
    float radius = 0.f;  // px from the centre
};

struct ClassRun {
    ColorClass colorClass = ColorClass::Unknown;
    int first = 0;  // index of the first pixel of the run in the ray
    int last = 0;   // index of the last pixel (inclusive)
    float startRadius = 0.f;
    float endRadius = 0.f;
};

class RadialSensors {
public:
    RadialSensors() = default;
    // Rays keep only pixels inside the image and used by the geometry, each pixel once.
    RadialSensors(const RadialSensorOptions& options, const Geometry& geometry);

    int count() const { return int(rays_.size()); }
    double angle(int ray) const;  // radians, 0 = +x, counter-clockwise in the image
    const std::vector<SensorPixel>& pixels(int ray) const { return rays_[std::size_t(ray)]; }

    // Runs of equal class along `ray` in a segmented image; `runs` is cleared and refilled
    // (keep it between frames: no allocation once it has grown).
    void runs(const cv::Mat& classes, int ray, std::vector<ClassRun>& runs) const;

private:
    RadialSensorOptions options_;
    std::vector<std::vector<SensorPixel>> rays_;
};

}  // namespace omnitune
