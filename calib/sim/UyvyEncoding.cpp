#include "calib/sim/UyvyEncoding.h"

#include <cstdint>

namespace omnitune {

void convertBgrToUyvy(const cv::Mat& bgr, cv::Mat& uyvy)
{
    CV_Assert(bgr.type() == CV_8UC3 && bgr.cols % 2 == 0);
    uyvy.create(bgr.size(), CV_8UC2);
    for (int y = 0; y < bgr.rows; ++y) {
        const std::uint8_t* in = bgr.ptr<std::uint8_t>(y);
        std::uint8_t* out = uyvy.ptr<std::uint8_t>(y);
        for (int x = 0; x < bgr.cols; x += 2, in += 6, out += 4) {
            double luma[2], u = 0.0, v = 0.0;
            for (int k = 0; k < 2; ++k) {
                const double b = in[3 * k], g = in[3 * k + 1], r = in[3 * k + 2];
                luma[k] = 0.299 * r + 0.587 * g + 0.114 * b;
                u += (b - luma[k]) / 1.772;
                v += (r - luma[k]) / 1.402;
            }
            out[0] = cv::saturate_cast<std::uint8_t>(128.0 + u / 2.0);
            out[1] = cv::saturate_cast<std::uint8_t>(luma[0]);
            out[2] = cv::saturate_cast<std::uint8_t>(128.0 + v / 2.0);
            out[3] = cv::saturate_cast<std::uint8_t>(luma[1]);
        }
    }
}

}  // namespace omnitune
