#pragma once
// Which ball search runs (thesis 4.1, 4.2, 4.3).
#include <optional>
#include <string_view>

namespace omnitune {

enum class Algorithm {
    Specific,  // the specific circular Hough transform
    OpenCv,    // cv::HoughCircles
    Combined,  // specific first, OpenCV when it finds no valid ball
};

std::string_view algorithmName(Algorithm a);
std::optional<Algorithm> parseAlgorithm(std::string_view name);

}  // namespace omnitune
