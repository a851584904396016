#include "calib/camera/MeanSampleValue.h"

namespace omnitune {

std::vector<double> regionHistogram(const cv::Mat& grey, const cv::Mat& mask, int regions)
{
    CV_Assert(grey.type() == CV_8UC1 && regions >= 1);
    CV_Assert(mask.empty() || (mask.type() == CV_8UC1 && mask.size() == grey.size()));
    std::vector<double> counts(std::size_t(regions), 0.0);
    for (int y = 0; y < grey.rows; ++y) {
        const uchar* g = grey.ptr<uchar>(y);
        const uchar* m = mask.empty() ? nullptr : mask.ptr<uchar>(y);
        for (int x = 0; x < grey.cols; ++x)
            if (!m || m[x]) counts[std::size_t(g[x] * regions / 256)] += 1.0;
    }
    return counts;
}

double meanSampleValue(const std::vector<double>& histogram)
{
    double weighted = 0.0, total = 0.0;
    for (std::size_t j = 0; j < histogram.size(); ++j) {
        weighted += double(j + 1) * histogram[j];
        total += histogram[j];
    }
    return total > 0.0 ? weighted / total : 0.0;
}

}  // namespace omnitune
