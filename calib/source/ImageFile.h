#pragma once
// Reads one image file as BGR; an empty Mat when it is missing, not a regular file (a FIFO
// would block the reader for good) or does not decode (OpenCV throws on some truncated files
// instead of returning empty: all mean "unreadable" here). `why`, when given, gets the reason.
#include "core/RegularFile.h"

#include <opencv2/imgcodecs.hpp>

#include <string>

namespace omnitune {

inline cv::Mat readImageFile(const std::string& path, std::string* why = nullptr)
{
    if (const auto notRegular = checkRegularFile(path)) {
        if (why) *why = *notRegular;
        return {};
    }
    try {
        cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
        if (image.empty() && why) *why = "does not decode as an image";
        return image;
    } catch (const cv::Exception&) {
        if (why) *why = "does not decode as an image";
        return {};
    }
}

}  // namespace omnitune
