#pragma once
// The pixels around one place of a judged frame, kept to be looked at later (omnitune-eval
// --fp-crops, --miss-crops): a false positive or a missed ball, enlarged with its circles drawn.
#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct FrameCrop {
    cv::Mat image;   // BGR, a copy (empty when the place lies outside the frame)
    cv::Point origin;  // its top-left pixel in the frame
};

// The square of half-side `half` px around (x, y), clipped to the frame.
FrameCrop cropAround(const cv::Mat& frame, double x, double y, int half);

// Around a circle (a detection, a ball) of `radius` px: kCropRadii radii (of at least 2 px) each
// side, enough to see what it touches.
constexpr double kCropRadii = 4.0;
FrameCrop cropAroundCircle(const cv::Mat& frame, double x, double y, double radius);

// A circle drawn on an enlarged crop, in frame px.
struct CropCircle {
    double x = 0, y = 0, radius = 0;
    cv::Scalar colour;
};

// Writes `crop` enlarged `scale` times (nearest neighbour) with `circles` drawn to `path`.
// Returns an error naming the file when it cannot be written; an empty crop writes nothing.
std::optional<std::string> writeEnlargedCrop(const std::string& path, const FrameCrop& crop, int scale,
                                             const std::vector<CropCircle>& circles);

// A file name part: letters and digits kept, everything else '-'.
std::string fileSafe(const std::string& s);

// Creates `folder` (and its parents) when missing; an error naming it when it cannot be.
std::optional<std::string> makeCropFolder(const std::string& folder);

}  // namespace omnitune
