#include "calib/colour/ClassShares.h"

#include <algorithm>

namespace omnitune {

bool boxesContain(const std::vector<HsvRange>& boxes, int h, int s, int v)
{
    for (const HsvRange& b : boxes)
        if (b.contains(h, s, v)) return true;
    return false;
}

ClassShares classShares(const cv::Mat& hsv, const cv::Mat& used, const ClassBoxes& classes)
{
    CV_Assert(hsv.type() == CV_8UC3 && (used.empty() || (used.type() == CV_8UC1 && used.size() == hsv.size())));
    ClassShares res;
    res.counts.assign(classes.size(), 0);
    res.overlap = cv::Mat(hsv.size(), CV_8UC1, cv::Scalar(0));
    for (int y = 0; y < hsv.rows; ++y) {
        const cv::Vec3b* row = hsv.ptr<cv::Vec3b>(y);
        const std::uint8_t* use = used.empty() ? nullptr : used.ptr<std::uint8_t>(y);
        std::uint8_t* over = res.overlap.ptr<std::uint8_t>(y);
        for (int x = 0; x < hsv.cols; ++x) {
            if (use && !use[x]) continue;
            ++res.processed;
            int first = -1;
            int claims = 0;
            for (std::size_t c = 0; c < classes.size() && claims < 2; ++c) {
                if (!boxesContain(classes[c], row[x][0], row[x][1], row[x][2])) continue;
                if (first < 0) first = int(c);
                ++claims;
            }
            if (first < 0) ++res.unclassified;
            else ++res.counts[std::size_t(first)];
            if (claims >= 2) {
                over[x] = 255;
                ++res.overlapCount;
            }
        }
    }
    return res;
}

void countSegmented(ClassShares& shares, const cv::Mat& classes, const cv::Mat& used)
{
    CV_Assert(classes.type() == CV_8UC1 && (used.empty() || (used.type() == CV_8UC1 && used.size() == classes.size())));
    shares.processed = 0;
    shares.unclassified = 0;
    std::fill(shares.counts.begin(), shares.counts.end(), 0);
    for (int y = 0; y < classes.rows; ++y) {
        const std::uint8_t* id = classes.ptr<std::uint8_t>(y);
        const std::uint8_t* use = used.empty() ? nullptr : used.ptr<std::uint8_t>(y);
        for (int x = 0; x < classes.cols; ++x) {
            if (use && !use[x]) continue;
            ++shares.processed;
            const std::size_t index = std::size_t(id[x]) - 1;
            if (id[x] == 0 || index >= shares.counts.size()) ++shares.unclassified;
            else ++shares.counts[index];
        }
    }
}

}  // namespace omnitune
