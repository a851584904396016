#pragma once
// The pixels a sampling gesture covers on an image pane: a click, a brush stroke of a given
// radius, or a rectangle. Clipped to the frame; each pixel once.
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

// Pixels of a disc of `radius` px around `centre` (radius 0: the one pixel).
std::vector<cv::Point> discPixels(cv::Point centre, int radius, cv::Size frame);
// Pixels a round brush of `radius` px covers when dragged along `path` (points in order).
std::vector<cv::Point> strokePixels(const std::vector<cv::Point>& path, int radius, cv::Size frame);
// Pixels of the rectangle spanned by two corners (inclusive).
std::vector<cv::Point> rectPixels(cv::Point a, cv::Point b, cv::Size frame);

}  // namespace omnitune
