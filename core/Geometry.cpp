#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <string>

namespace omnitune {

Geometry::Geometry(const GeometryOptions& options, const cv::Mat& mask) : options_(options)
{
    const int w = options.imageWidth;
    const int h = options.imageHeight;
    // The size and the mask are checked once, by checkConfig() (it names the mask file); this
    // guards the per-pixel tables against a caller that skipped it.
    CV_Assert(w > 0 && h > 0);
    CV_Assert(mask.empty() || (mask.cols == w && mask.rows == h && mask.type() == CV_8UC1));
    used_.create(h, w, CV_8UC1);
    cv::Mat masked(h, w, CV_8UC1, cv::Scalar(0));
    bool anyMasked = false;
    distance_.create(h, w, CV_32FC1);
    const double inner2 = options.innerRadius * options.innerRadius;
    const double outer2 = options.outerRadius * options.outerRadius;
    for (int y = 0; y < h; ++y) {
        float* dist = distance_.ptr<float>(y);
        std::uint8_t* used = used_.ptr<std::uint8_t>(y);
        const std::uint8_t* m = mask.empty() ? nullptr : mask.ptr<std::uint8_t>(y);
        const double dy = y - options.centerY;
        int spanStart = -1;
        for (int x = 0; x < w; ++x) {
            const double dx = x - options.centerX;
            const double d2 = dx * dx + dy * dy;
            dist[x] = float(std::sqrt(d2));
            const bool inRing = d2 >= inner2 && d2 <= outer2;
            used[x] = (inRing && (!m || m[x] != 0)) ? 255 : 0;
            if (inRing && !used[x]) {
                masked.at<std::uint8_t>(y, x) = 255;
                anyMasked = true;
            }
            if (used[x]) {
                usedPixels_.push_back(y * w + x);
                if (spanStart < 0) spanStart = x;
            } else if (spanStart >= 0) {
                spans_.push_back({y, spanStart, x});
                spanStart = -1;
            }
        }
        if (spanStart >= 0) spans_.push_back({y, spanStart, w});
    }
    if (anyMasked) maskedInRing_ = masked;
    cv::erode(used_, edgeMask_, cv::Mat(), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
}

}  // namespace omnitune
