#pragma once
// The binary image with its masked ring pixels (support rods, reflections) taken from their
// surroundings: a masked pixel within `px` of a non-green pixel becomes non-green (the darkest
// level in its (2 px + 1)-square). The binary image paints masked pixels green, so a ball behind
// a rod reaches cv::HoughCircles as two half discs with straight borders along the rod, which
// vote for no circle; filled, the ball is whole again, and a rod across bare carpet stays green.
// A masked pixel farther than `px` from anything non-green stays as it was.
#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

class MaskFill {
public:
    // `binary` itself when px <= 0 or the ring has no masked pixel; else the filled copy (kept
    // until the next call).
    const cv::Mat& apply(const cv::Mat& binary, const Geometry& geometry, int px);

private:
    cv::Mat kernel_;
    int kernelPx_ = 0;
    cv::Mat darkest_;
    cv::Mat filled_;
};

}  // namespace omnitune
