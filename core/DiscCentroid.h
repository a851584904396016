#pragma once
// The centroid of the pixels within `reach` of `p` (inside an image of `size`) that `counts(x, y)`
// accepts; `p` itself when it accepts none. The centre refinements of the OpenCV search and of
// the recentred refusals differ only in which pixels they count.
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace omnitune {

template <class Counts>
cv::Point2d discCentroid(cv::Size size, cv::Point2d p, double reach, Counts counts)
{
    double sx = 0, sy = 0;
    long n = 0;
    const int y0 = std::max(0, int(std::floor(p.y - reach)));
    const int y1 = std::min(size.height - 1, int(std::ceil(p.y + reach)));
    const int x0 = std::max(0, int(std::floor(p.x - reach)));
    const int x1 = std::min(size.width - 1, int(std::ceil(p.x + reach)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            if ((x - p.x) * (x - p.x) + (y - p.y) * (y - p.y) > reach * reach || !counts(x, y)) continue;
            sx += x;
            sy += y;
            ++n;
        }
    return n > 0 ? cv::Point2d(sx / double(n), sy / double(n)) : p;
}

}  // namespace omnitune
