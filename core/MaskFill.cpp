#include "core/MaskFill.h"

#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

namespace omnitune {

const cv::Mat& MaskFill::apply(const cv::Mat& binary, const Geometry& geometry, int px)
{
    const cv::Mat& masked = geometry.maskedInRing();
    if (px <= 0 || masked.empty()) return binary;
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == masked.size());
    if (kernelPx_ != px) {
        // A square: OpenCV erodes with a rectangle in two 1-D passes, whatever its size.
        kernel_ = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * px + 1, 2 * px + 1));
        kernelPx_ = px;
    }
    cv::erode(binary, darkest_, kernel_, cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
    binary.copyTo(filled_);
    darkest_.copyTo(filled_, masked);
    return filled_;
}

}  // namespace omnitune
