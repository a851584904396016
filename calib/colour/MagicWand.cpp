#include "calib/colour/MagicWand.h"

#include "calib/colour/HueArc.h"

#include <cstdlib>

namespace omnitune {

std::vector<cv::Point> magicWand(const cv::Mat& hsv, const cv::Mat& used, cv::Point seed, const WandTolerance& tol)
{
    CV_Assert(hsv.type() == CV_8UC3 && (used.empty() || (used.type() == CV_8UC1 && used.size() == hsv.size())));
    std::vector<cv::Point> region;
    const cv::Rect frame({}, hsv.size());
    auto usable = [&](cv::Point p) { return frame.contains(p) && (used.empty() || used.at<std::uint8_t>(p) != 0); };
    if (!usable(seed)) return region;

    const cv::Vec3b s0 = hsv.at<cv::Vec3b>(seed);
    const bool useHue = s0[1] >= tol.achromaticS;
    auto similar = [&](const cv::Vec3b& c) {
        if (std::abs(int(c[1]) - s0[1]) > tol.s || std::abs(int(c[2]) - s0[2]) > tol.v) return false;
        if (!useHue) return true;
        const int d = wrapHue(int(c[0]) - s0[0]);
        return std::min(d, kHueSteps - d) <= tol.h;
    };

    cv::Mat seen(hsv.size(), CV_8UC1, cv::Scalar(0));
    std::vector<cv::Point> todo{seed};
    seen.at<std::uint8_t>(seed) = 1;
    const cv::Point steps[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    while (!todo.empty()) {
        const cv::Point p = todo.back();
        todo.pop_back();
        region.push_back(p);
        if (tol.maxPixels > 0 && int(region.size()) >= tol.maxPixels) break;
        for (const cv::Point& d : steps) {
            const cv::Point q = p + d;
            if (!usable(q) || seen.at<std::uint8_t>(q)) continue;
            seen.at<std::uint8_t>(q) = 1;
            if (similar(hsv.at<cv::Vec3b>(q))) todo.push_back(q);
        }
    }
    return region;
}

}  // namespace omnitune
