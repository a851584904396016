#include "calib/mask/AutoMask.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace omnitune {

namespace {

AutoMaskResult failure(FitErrorKind kind, std::string message)
{
    AutoMaskResult r;
    r.error = FitError{kind, std::move(message)};
    return r;
}

cv::Mat toBgr(const cv::Mat& frame)
{
    if (frame.type() == CV_8UC3) return frame;
    cv::Mat bgr;
    convertUyvyToBgr(frame, bgr);
    return bgr;
}

std::uint8_t median(std::vector<std::uint8_t>& values)
{
    const auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

}  // namespace

AutoMaskResult autoMask(const std::vector<cv::Mat>& frames, const GeometryOptions& geometry, const ColorLut& lut,
                        const AutoMaskOptions& options, Progress* progress)
{
    const int n = int(frames.size());
    if (n < options.minFrames)
        return failure(FitErrorKind::TooFewFrames,
                       "the auto-mask needs at least " + std::to_string(options.minFrames) + " frames, got " +
                           std::to_string(n) + ": use a session in which the robot drives or turns");
    const cv::Size size(geometry.imageWidth, geometry.imageHeight);
    std::vector<cv::Mat> bgr;
    bgr.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i) {
        const cv::Mat& f = frames[std::size_t(i)];
        if (f.size() != size || (f.type() != CV_8UC3 && f.type() != CV_8UC2))
            return failure(FitErrorKind::BadInput, "frame " + std::to_string(i + 1) + " is " + std::to_string(f.cols) +
                                                       "x" + std::to_string(f.rows) + " with " +
                                                       std::to_string(f.channels()) +
                                                       " channel(s); the auto-mask needs " + std::to_string(size.width) +
                                                       "x" + std::to_string(size.height) + " BGR or UYVY frames");
        bgr.push_back(toBgr(f));
    }

    AutoMask fit;
    fit.frames = n;
    cv::Mat robot(size, CV_8UC1, cv::Scalar(0));
    const double r2 = geometry.outerRadius * geometry.outerRadius;
    const int maxChanges = int(std::floor(options.maxChangeShare * n));
    std::array<std::vector<std::uint8_t>, 3> channel;
    for (auto& c : channel) c.resize(std::size_t(n));
    long ringPixels = 0, moving = 0;
    for (int y = 0; y < size.height; ++y) {
        if (progress) {
            if (progress->isCancelRequested()) return failure(FitErrorKind::Cancelled, "the auto-mask was cancelled");
            if (y % 32 == 0) progress->update(100.0 * y / size.height);
        }
        const double dy = y - geometry.centerY;
        std::uint8_t* out = robot.ptr<std::uint8_t>(y);
        for (int x = 0; x < size.width; ++x) {
            const double dx = x - geometry.centerX;
            if (dx * dx + dy * dy > r2) continue;
            ++ringPixels;
            for (int i = 0; i < n; ++i) {
                const cv::Vec3b p = bgr[std::size_t(i)].at<cv::Vec3b>(y, x);
                for (int c = 0; c < 3; ++c) channel[std::size_t(c)][std::size_t(i)] = p[c];
            }
            cv::Vec3b m;
            for (int c = 0; c < 3; ++c) m[c] = median(channel[std::size_t(c)]);
            int changes = 0;
            for (int i = 0; i < n; ++i) {
                const cv::Vec3b p = bgr[std::size_t(i)].at<cv::Vec3b>(y, x);
                const int d = std::max({std::abs(p[0] - m[0]), std::abs(p[1] - m[1]), std::abs(p[2] - m[2])});
                if (d > options.changeLevel) ++changes;
            }
            // Whether the field moved is judged on every pixel of the ring: on a plain carpet
            // only the lines, the ball and other robots change, and their median is carpet.
            if (changes > maxChanges) {
                ++moving;
                continue;
            }
            // A still carpet is field, not robot.
            if (lut.isField(lut.classifyBgr(m[0], m[1], m[2]))) continue;
            out[x] = 255;
        }
    }
    if (double(moving) < options.minMovingShare * double(ringPixels))
        return failure(FitErrorKind::StaticField,
                       "nothing but carpet moved between the " + std::to_string(n) +
                           " frames: the auto-mask needs frames in which the robot drives or turns");

    if (options.openPx > 0) {
        const int k = 2 * options.openPx + 1;
        cv::morphologyEx(robot, robot, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {k, k}));
    }
    cv::Mat labels, stats, centroids;
    const int count = cv::connectedComponentsWithStats(robot, labels, stats, centroids, 8, CV_32S);
    cv::Mat kept(size, CV_8UC1, cv::Scalar(0));
    for (int label = 1; label < count; ++label) {
        if (stats.at<int>(label, cv::CC_STAT_AREA) < options.minRegionPx) continue;
        kept.setTo(255, labels == label);
        ++fit.regions;
    }
    if (options.growPx > 0) {
        const int k = 2 * options.growPx + 1;
        cv::dilate(kept, kept, cv::getStructuringElement(cv::MORPH_ELLIPSE, {k, k}));
    }
    fit.robotShare = ringPixels > 0 ? double(cv::countNonZero(kept)) / double(ringPixels) : 0.0;
    cv::bitwise_not(kept, fit.mask);
    if (progress) progress->update(100.0);
    AutoMaskResult r;
    r.fit = std::move(fit);
    return r;
}

}  // namespace omnitune
