#include "calib/colour/ColourSamples.h"

namespace omnitune {

void ColourSamples::append(const ColourSamples& more)
{
    hsv.insert(hsv.end(), more.hsv.begin(), more.hsv.end());
    masked += more.masked;
}

ColourSamples sampleColours(const cv::Mat& frame, PixelFormat format, const cv::Mat& used,
                            const std::vector<cv::Point>& pixels)
{
    CV_Assert(used.empty() || (used.type() == CV_8UC1 && used.size() == frame.size()));
    ColourSamples out;
    out.hsv.reserve(pixels.size());
    const FrameColour colour(frame, format);
    const cv::Rect inside({}, frame.size());
    for (const cv::Point& p : pixels) {
        if (!inside.contains(p)) continue;
        if (!used.empty() && used.at<std::uint8_t>(p) == 0) {
            ++out.masked;
            continue;
        }
        out.hsv.push_back(colour.hsvAt(p.x, p.y));
    }
    return out;
}

}  // namespace omnitune
