#include "core/Pipeline.h"

#include "core/BallPosition.h"
#include "core/ConfigSchema.h"
#include "core/FillBytes.h"

#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace omnitune {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point& t)
{
    const auto now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
    return ms;
}

// The chosen ball: the valid candidate with the best circularity, then the most votes.
int chooseCandidate(std::vector<BallCandidate>& candidates)
{
    int best = -1;
    for (int i = 0; i < int(candidates.size()); ++i) {
        const BallCandidate& c = candidates[std::size_t(i)];
        if (c.rejected != RejectReason::None) continue;
        if (best < 0) {
            best = i;
            continue;
        }
        const BallCandidate& b = candidates[std::size_t(best)];
        if (c.scores.circularityPct > b.scores.circularityPct ||
            (c.scores.circularityPct == b.scores.circularityPct && c.accumulator > b.accumulator))
            best = i;
    }
    for (int i = 0; i < int(candidates.size()); ++i)
        if (i != best && candidates[std::size_t(i)].rejected == RejectReason::None)
            candidates[std::size_t(i)].rejected = RejectReason::NotChosen;
    return best;
}

}  // namespace

struct Pipeline::Impl {
    Config config;
    ColorLut lut;
    Geometry geometry;
    DistanceMap distanceMap;
    BallModel ball;
    SpecificHough hough;
    OpenCvHough opencvHough;
    CannyDetector canny;
    cv::Mat binary;
    cv::Mat edges;

    void validateFrom(std::size_t first, PipelineResult& r)
    {
        for (std::size_t i = first; i < r.candidates.size(); ++i)
            validateCandidate(r.candidates[i], r.classes, edges, geometry, ball, config.validation);
    }
    bool anyValid(const PipelineResult& r) const
    {
        for (const auto& c : r.candidates)
            if (c.rejected == RejectReason::None) return true;
        return false;
    }
};

Pipeline::Pipeline(const Config& config) : impl_(std::make_unique<Impl>()) { setConfig(config); }
Pipeline::~Pipeline() = default;

void Pipeline::setConfig(const Config& config)
{
    const auto problems = checkConfig(config);
    if (!problems.empty()) throw std::invalid_argument(problems.front().toString());
    auto next = std::make_unique<Impl>();
    next->config = config;
    next->lut.compile(config.colors);
    next->geometry = Geometry(config.geometry, config.mask);
    next->distanceMap = DistanceMap(config.distanceMap);
    next->ball = BallModel(config.ball);
    next->hough = SpecificHough(config.hough, next->geometry, next->ball);
    impl_ = std::move(next);  // only a fully built pipeline replaces the old one
}

const Config& Pipeline::config() const { return impl_->config; }

void Pipeline::reset() {}

void Pipeline::process(const cv::Mat& frame, PixelFormat format, PipelineResult& r, bool wantStageImages)
{
    Impl& p = *impl_;
    r.error.clear();
    r.candidates.clear();
    r.detection = BallDetection{};
    r.timings = StageTimings{};
    const cv::Size size = p.geometry.imageSize();
    const int expectedType = format == PixelFormat::Bgr8 ? CV_8UC3 : CV_8UC2;
    if (frame.empty()) {
        r.error = "the frame is empty (unreadable image?)";
        return;
    }
    if (frame.type() != expectedType) {
        r.error = "the frame has " + std::to_string(frame.channels()) + " channel(s) of depth " +
                  std::to_string(frame.depth()) + "; " + std::string(pixelFormatName(format)) + " needs " +
                  (format == PixelFormat::Bgr8 ? "3" : "2") + " 8-bit channels";
        return;
    }
    if (format == PixelFormat::Uyvy && frame.cols % 2 != 0) {
        r.error = "a UYVY frame needs an even width (pixel pairs share U and V); this one is " +
                  std::to_string(frame.cols) + " px wide";
        return;
    }
    if (frame.size() != size) {
        r.error = "the frame is " + std::to_string(frame.cols) + "x" + std::to_string(frame.rows) +
                  " but the config's geometry is for " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                  " (geometry.image_width/height)";
        return;
    }

    auto start = Clock::now();
    auto t = start;
    r.classes.create(size, CV_8UC1);
    fillBytes(r.classes, 0);
    p.lut.segment(frame, format, p.geometry.spans(), r.classes);
    r.timings.segmentMs = msSince(t);
    makeBinary(r.classes, p.geometry, p.binary);
    r.timings.binaryMs = msSince(t);
    p.canny.detect(p.binary, p.config.edges, p.edges);
    cv::bitwise_and(p.edges, p.geometry.edgeMask(), p.edges);
    r.timings.edgesMs = msSince(t);

    const Algorithm alg = p.config.algorithm;
    if (alg == Algorithm::Specific || alg == Algorithm::Combined) {
        p.hough.process(p.edges, p.binary, r.candidates);
        r.timings.houghMs += msSince(t);
        p.validateFrom(0, r);
        r.timings.validationMs += msSince(t);
    }
    if (alg == Algorithm::OpenCv || (alg == Algorithm::Combined && !p.anyValid(r))) {
        const std::size_t first = r.candidates.size();
        p.opencvHough.process(p.binary, p.config.opencvHough, p.geometry, p.ball, r.candidates);
        r.timings.houghMs += msSince(t);
        p.validateFrom(first, r);
        r.timings.validationMs += msSince(t);
    }

    const int best = chooseCandidate(r.candidates);
    if (best >= 0) {
        const BallCandidate& c = r.candidates[std::size_t(best)];
        BallDetection& d = r.detection;
        d.found = true;
        d.candidate = best;
        d.px = c.x;
        d.py = c.y;
        d.radiusPx = c.radiusPx;
        const BallPosition at = ballPositionAt(c.x, c.y, p.config.geometry.centerX, p.config.geometry.centerY, p.distanceMap);
        d.distancePx = at.distancePx;
        d.distanceM = at.distanceM;
        d.xM = at.xM;
        d.yM = at.yM;
    }
    r.timings.totalMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();

    if (!wantStageImages) return;
    StageImages& s = r.stages;
    if (format == PixelFormat::Bgr8)
        frame.copyTo(s.acquired);
    else
        convertUyvyToBgr(frame, s.acquired);
    s.segmented.create(size, CV_8UC3);
    for (int y = 0; y < size.height; ++y) {
        const std::uint8_t* c = r.classes.ptr<std::uint8_t>(y);
        const std::uint8_t* u = p.geometry.usedMask().ptr<std::uint8_t>(y);
        cv::Vec3b* out = s.segmented.ptr<cv::Vec3b>(y);
        for (int x = 0; x < size.width; ++x) {
            const auto bgr = colorClassDisplayBgr(static_cast<ColorClass>(c[x]));
            out[x] = u[x] ? cv::Vec3b(bgr[0], bgr[1], bgr[2]) : cv::Vec3b(40, 40, 40);
        }
    }
    p.binary.copyTo(s.grayscale);
    p.edges.copyTo(s.edges);
    double maxSum = 0;
    cv::minMaxLoc(p.hough.sums(), nullptr, &maxSum);
    cv::Mat scaled;
    p.hough.sums().convertTo(scaled, CV_8U, maxSum > 0 ? 255.0 / maxSum : 0.0);
    cv::applyColorMap(scaled, s.hough, cv::COLORMAP_JET);
}

}  // namespace omnitune
