#pragma once
// The edge stage: segmented classes -> binary image (green and unprocessed pixels white,
// everything else black; thesis "Grayscale Image") -> Canny edges ("Edges Image"). Or, the
// thesis' solutions 2 and 4, Canny on the grayscale of the camera frame itself.
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace omnitune {

class Geometry;

// What Canny (and cv::HoughCircles) see.
enum class EdgeInput {
    Binary,  // the green / non-green image made from the colour classes (thesis ch. 4)
    Gray,    // the frame's own grayscale, no colour segmentation (thesis solutions 2 and 4)
};
std::string_view edgeInputName(EdgeInput input);
std::optional<EdgeInput> parseEdgeInput(std::string_view name);

struct EdgeOptions {
    int cannyLow = 60;   // hysteresis low threshold on |dx|+|dy| of a 3x3 Sobel; 0..1020
    int cannyHigh = 180; // high threshold; edges start above it and grow above cannyLow
    // Level of white (line) pixels in the binary image; 0 is the thesis (white is non-green like
    // the ball). A level between 0 and 255 puts an edge between a ball and a line it touches.
    // Used rounded down to a multiple of 16: the Hough's centre test reads the binary image's
    // low bits as "not green" (weight & ~binary).
    int whiteLevel = 0;
    EdgeInput input = EdgeInput::Binary;
    // On the binary input, raise both thresholds to just below a straight border's gradient
    // (core/SpeckFreeEdges.h): the ring of edges around a one-pixel speck drops out, every border
    // stays. Off: the thesis, the thresholds as set.
    bool dropSpecks = true;
};

// The level makeBinary gives line pixels: white_level rounded down to a multiple of 16, so that the
// Hough's centre test can read the binary image's low bits as "not green".
inline int binaryWhiteLevel(int whiteLevel) { return whiteLevel & 0xF0; }

// Field classes ("green") -> 255, line classes ("white") -> binaryWhiteLevel, other classes -> 0,
// pixels the geometry does not use -> 255 so that the robot body and the mirror rim make no edges.
void makeBinary(const cv::Mat& classes, const Geometry& geometry, cv::Mat& binary, int whiteLevel = 0,
                const ColourRoles& roles = defaultColourRoles());

// The luminance of a BGR or UYVY frame (CV_8UC1), for EdgeInput::Gray; `gray` is reused.
void makeGray(const cv::Mat& frame, bool uyvy, cv::Mat& gray);

// Canny edge detector (3x3 Sobel, L1 magnitude, replicated border, OpenCV's direction
// quantisation). Written here instead of calling cv::Canny so that it keeps its scratch
// buffers between frames (no allocation per frame once warm).
class CannyDetector {
public:
    void detect(const cv::Mat& gray, const EdgeOptions& options, cv::Mat& edges);

private:
    // L1 Sobel magnitude (at most 8 x 255, so 16 bits) with a one-pixel zero border; the border
    // is written only when the image size changes, the interior on every frame.
    std::vector<std::int16_t> magnitude_;
    cv::Size size_;
    std::vector<std::uint8_t> state_;  // per pixel: 0 none, 1 weak candidate, 2 edge
    std::vector<int> stack_;
};

}  // namespace omnitune
