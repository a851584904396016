#include "calib/fit/GrayFrames.h"

#include <opencv2/imgproc.hpp>

#include <string>

namespace omnitune {

std::optional<FitError> toGrayFrames(const std::vector<cv::Mat>& frames, std::vector<cv::Mat>& gray)
{
    gray.clear();
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const cv::Mat& f = frames[i];
        const std::string which = "frame " + std::to_string(i + 1) + " of " + std::to_string(frames.size());
        if (f.empty()) return FitError{FitErrorKind::BadInput, which + " is empty"};
        if (f.size() != frames.front().size())
            return FitError{FitErrorKind::BadInput, which + " is " + std::to_string(f.cols) + "x" + std::to_string(f.rows) +
                                                        " but the first is " + std::to_string(frames.front().cols) + "x" +
                                                        std::to_string(frames.front().rows) + ": use frames of one camera"};
        cv::Mat g;
        if (f.type() == CV_8UC3) cv::cvtColor(f, g, cv::COLOR_BGR2GRAY);
        else if (f.type() == CV_8UC2) cv::cvtColor(f, g, cv::COLOR_YUV2GRAY_UYVY);
        else if (f.type() == CV_8UC1) g = f;
        else return FitError{FitErrorKind::BadInput, which + " is not an 8-bit BGR, grey or UYVY image"};
        g.convertTo(g, CV_32F);
        gray.push_back(g);
    }
    return std::nullopt;
}

}  // namespace omnitune
