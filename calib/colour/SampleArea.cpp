#include "calib/colour/SampleArea.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace omnitune {

namespace {

std::vector<cv::Point> pixelsOf(const cv::Mat& painted)
{
    std::vector<cv::Point> out;
    cv::findNonZero(painted, out);
    return out;
}

}  // namespace

std::vector<cv::Point> discPixels(cv::Point centre, int radius, cv::Size frame)
{
    return strokePixels({centre}, radius, frame);
}

std::vector<cv::Point> strokePixels(const std::vector<cv::Point>& path, int radius, cv::Size frame)
{
    // Painting into a frame-sized mask gives each pixel once however often the brush passes.
    cv::Mat painted(frame, CV_8UC1, cv::Scalar(0));
    const int r = std::max(0, radius);
    // A disc at every pixel of the path (OpenCV's thick lines are wider than 2r + 1).
    auto dab = [&](cv::Point p) { cv::circle(painted, p, r, cv::Scalar(255), cv::FILLED, cv::LINE_8); };
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (i == 0) {
            dab(path[0]);
            continue;
        }
        cv::LineIterator it(path[i - 1], path[i], 8);
        for (int k = 0; k < it.count; ++k, ++it) dab(it.pos());
    }
    return pixelsOf(painted);
}

std::vector<cv::Point> rectPixels(cv::Point a, cv::Point b, cv::Size frame)
{
    const cv::Rect r = cv::Rect(cv::Point(std::min(a.x, b.x), std::min(a.y, b.y)),
                                cv::Point(std::max(a.x, b.x) + 1, std::max(a.y, b.y) + 1)) &
                       cv::Rect({}, frame);
    std::vector<cv::Point> out;
    out.reserve(std::size_t(r.area()));
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x) out.emplace_back(x, y);
    return out;
}

}  // namespace omnitune
