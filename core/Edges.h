#pragma once
// The edge stage: segmented classes -> binary image (green and unprocessed pixels white,
// everything else black; thesis "Grayscale Image") -> Canny edges ("Edges Image").
#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace omnitune {

class Geometry;

struct EdgeOptions {
    int cannyLow = 60;   // hysteresis low threshold on |dx|+|dy| of a 3x3 Sobel; 0..1020
    int cannyHigh = 180; // high threshold; edges start above it and grow above cannyLow
};

// Green -> 255, other classes -> 0, pixels the geometry does not use -> 255 so that the robot
// body and the mirror rim make no edges.
void makeBinary(const cv::Mat& classes, const Geometry& geometry, cv::Mat& binary);

// Canny edge detector (3x3 Sobel, L1 magnitude, replicated border, OpenCV's direction
// quantisation). Written here instead of calling cv::Canny so that it keeps its scratch
// buffers between frames (no allocation per frame once warm).
class CannyDetector {
public:
    void detect(const cv::Mat& gray, const EdgeOptions& options, cv::Mat& edges);

private:
    std::vector<std::int32_t> magnitude_;
    std::vector<std::uint8_t> state_;  // per pixel: 0 none, 1 weak candidate, 2 edge
    std::vector<std::int16_t> dx_;
    std::vector<std::int16_t> dy_;
    std::vector<int> stack_;
};

}  // namespace omnitune
