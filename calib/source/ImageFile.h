#pragma once
// Reads one image file as BGR; an empty Mat when it is missing or does not decode (OpenCV
// throws on some truncated files instead of returning empty: both mean "unreadable" here).
#include <opencv2/imgcodecs.hpp>

#include <string>

namespace omnitune {

inline cv::Mat readImageFile(const std::string& path)
{
    try {
        return cv::imread(path, cv::IMREAD_COLOR);
    } catch (const cv::Exception&) {
        return {};
    }
}

}  // namespace omnitune
