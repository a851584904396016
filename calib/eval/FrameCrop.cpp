#include "calib/eval/FrameCrop.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace omnitune {

FrameCrop cropAround(const cv::Mat& frame, double x, double y, int half)
{
    FrameCrop crop;
    const cv::Rect box =
        cv::Rect(int(x) - half, int(y) - half, 2 * half + 1, 2 * half + 1) & cv::Rect(0, 0, frame.cols, frame.rows);
    if (box.area() > 0) {
        crop.image = frame(box).clone();
        crop.origin = box.tl();
    }
    return crop;
}

FrameCrop cropAroundCircle(const cv::Mat& frame, double x, double y, double radius)
{
    return cropAround(frame, x, y, int(std::ceil(kCropRadii * std::max(2.0, radius))));
}

std::optional<std::string> writeEnlargedCrop(const std::string& path, const FrameCrop& crop, int scale,
                                             const std::vector<CropCircle>& circles)
{
    if (crop.image.empty()) return std::nullopt;
    cv::Mat big;
    cv::resize(crop.image, big, cv::Size(), scale, scale, cv::INTER_NEAREST);
    for (const CropCircle& c : circles) {
        const cv::Point at(int((c.x - crop.origin.x + 0.5) * scale), int((c.y - crop.origin.y + 0.5) * scale));
        cv::circle(big, at, int(c.radius * scale), c.colour, 1, cv::LINE_AA);
    }
    if (!cv::imwrite(path, big)) return path + ": cannot be written";
    return std::nullopt;
}

std::string fileSafe(const std::string& s)
{
    std::string out = s;
    for (char& ch : out)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '-';
    return out;
}

std::optional<std::string> makeCropFolder(const std::string& folder)
{
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) return folder + ": cannot be created (" + ec.message() + ")";
    return std::nullopt;
}

}  // namespace omnitune
