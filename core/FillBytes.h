#pragma once
// Sets every byte of a matrix, row by row. cv::Mat::setTo allocates a small buffer on every
// call (OpenCV 4.6), which the per-frame path must not do.
#include <opencv2/core.hpp>

#include <cstring>

namespace omnitune {

inline void fillBytes(cv::Mat& m, unsigned char value)
{
    const std::size_t rowBytes = std::size_t(m.cols) * m.elemSize();
    for (int y = 0; y < m.rows; ++y) std::memset(m.ptr(y), value, rowBytes);
}

}  // namespace omnitune
