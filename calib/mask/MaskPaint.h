#pragma once
// Painting on a mask image (issue 11's mask editor): a round brush dragged along a stroke, a
// filled polygon and a flood fill. Pure pixel work on a CV_8UC1 mask (255 = process, 0 = robot),
// so the window's editor and the tests agree on exactly which pixels a gesture changes.
// Positions are in image px as the panes report them: pixel (x, y) covers [x, x+1) x [y, y+1),
// and a gesture covers a pixel when it covers the pixel's centre (x + 0.5, y + 0.5).
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

// Mask values: what the detector does with a pixel.
inline constexpr std::uint8_t kMaskRobot = 0;        // never processed (body, rods)
inline constexpr std::uint8_t kMaskProcessed = 255;  // processed

// Every pixel whose centre lies within `radius` of the segment from `a` to `b` (a dot when
// a == b) becomes `value`. Returns how many pixels changed. Parts off the image are ignored.
int paintStroke(cv::Mat& mask, cv::Point2d a, cv::Point2d b, double radius, std::uint8_t value);

// Every pixel whose centre lies inside the closed polygon (even-odd rule: a self-crossing
// outline leaves its doubly enclosed parts alone) becomes `value`. Fewer than three vertices
// change nothing. Returns how many pixels changed.
int fillPolygon(cv::Mat& mask, const std::vector<cv::Point2d>& vertices, std::uint8_t value);

// The 4-connected region of the seed's value that holds `seed` becomes `value` (a robot region
// cleared, or a hole in a painted body filled). A seed off the image, or already of `value`,
// changes nothing. Returns how many pixels changed.
int floodFillMask(cv::Mat& mask, cv::Point2d seed, std::uint8_t value);

}  // namespace omnitune
