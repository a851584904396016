#include "core/Pipeline.h"

#include "core/BallPosition.h"
#include "core/CandidatePrefilter.h"
#include "core/CandidateScore.h"
#include "core/ConfigSchema.h"
#include "core/FrameColour.h"
#include "core/FrameDenoise.h"
#include "core/FrontEnd.h"
#include "core/FitRecentre.h"
#include "core/RefusalRecentre.h"
#include "core/SpeckFreeEdges.h"
#include "core/Stopwatch.h"

#include <opencv2/imgproc.hpp>

#include <array>
#include <cmath>
#include <stdexcept>

namespace omnitune {

namespace {

// Why `frame` cannot be processed with a geometry for `size`; empty when it can.
std::string frameProblem(const cv::Mat& frame, PixelFormat format, cv::Size size)
{
    const int expectedType = format == PixelFormat::Bgr8 ? CV_8UC3 : CV_8UC2;
    if (frame.empty()) return "the frame is empty (unreadable image?)";
    if (frame.type() != expectedType)
        return "the frame has " + std::to_string(frame.channels()) + " channel(s) of depth " +
               std::to_string(frame.depth()) + "; " + std::string(pixelFormatName(format)) + " needs " +
               (format == PixelFormat::Bgr8 ? "3" : "2") + " 8-bit channels";
    if (format == PixelFormat::Uyvy && frame.cols % 2 != 0)
        return "a UYVY frame needs an even width (pixel pairs share U and V); this one is " +
               std::to_string(frame.cols) + " px wide";
    if (frame.size() != size)
        return "the frame is " + std::to_string(frame.cols) + "x" + std::to_string(frame.rows) +
               " but the config's geometry is for " + std::to_string(size.width) + "x" +
               std::to_string(size.height) + " (geometry.image_width/height)";
    return {};
}

bool anyValid(const std::vector<BallCandidate>& candidates)
{
    for (const auto& c : candidates)
        if (c.rejected == RejectReason::None) return true;
    return false;
}

// Scores every candidate (shown for the rejected ones too) and chooses the valid one that
// preferCandidate() puts first; the other valid ones become NotChosen.
int chooseCandidate(std::vector<BallCandidate>& candidates, bool byScore)
{
    int best = -1;
    for (int i = 0; i < int(candidates.size()); ++i) {
        BallCandidate& c = candidates[std::size_t(i)];
        c.score = candidateScore(c);
        if (c.rejected != RejectReason::None) continue;
        if (best < 0 || preferCandidate(c, candidates[std::size_t(best)], byScore)) best = i;
    }
    for (int i = 0; i < int(candidates.size()); ++i)
        if (i != best && candidates[std::size_t(i)].rejected == RejectReason::None)
            candidates[std::size_t(i)].rejected = RejectReason::NotChosen;
    return best;
}

// The detection of candidate `index`: its pixel position and where that is on the field.
BallDetection detectionOf(const BallCandidate& c, int index, const GeometryOptions& geometry,
                          const DistanceMap& distanceMap)
{
    BallDetection d;
    d.found = true;
    d.candidate = index;
    d.px = c.x;
    d.py = c.y;
    d.radiusPx = c.radiusPx;
    const BallPosition at = ballPositionAt(c.x, c.y, geometry.centerX, geometry.centerY, distanceMap);
    d.distancePx = at.distancePx;
    d.distanceM = at.distanceM;
    d.xM = at.xM;
    d.yM = at.yM;
    return d;
}

// Classes in their display colours (unknown mid grey); pixels the geometry does not process in
// dark grey.
void paintSegmented(const cv::Mat& classes, const cv::Mat& usedMask, const ColourClasses& defs, cv::Mat& out)
{
    std::array<cv::Vec3b, 256> colour;
    colour.fill(cv::Vec3b(128, 128, 128));
    for (std::size_t i = 0; i < defs.size() && i < std::size_t(kMaxColourClasses); ++i)
        colour[i + 1] = cv::Vec3b(defs[i].display[0], defs[i].display[1], defs[i].display[2]);
    out.create(classes.size(), CV_8UC3);
    for (int y = 0; y < classes.rows; ++y) {
        const std::uint8_t* c = classes.ptr<std::uint8_t>(y);
        const std::uint8_t* u = usedMask.ptr<std::uint8_t>(y);
        cv::Vec3b* row = out.ptr<cv::Vec3b>(y);
        for (int x = 0; x < classes.cols; ++x) row[x] = u[x] ? colour[c[x]] : cv::Vec3b(40, 40, 40);
    }
}

// The 3x3 vote sums as a heat map scaled to their maximum.
void paintVotes(const cv::Mat& sums, cv::Mat& out)
{
    double maxSum = 0;
    cv::minMaxLoc(sums, nullptr, &maxSum);
    cv::Mat scaled;
    sums.convertTo(scaled, CV_8U, maxSum > 0 ? 255.0 / maxSum : 0.0);
    cv::applyColorMap(scaled, out, cv::COLORMAP_JET);
}

}  // namespace

struct Pipeline::Impl {
    explicit Impl(const Config& c)
        : config(c), denoiser(c.denoise), frontEnd(c), distanceMap(c.distanceMap), ball(c.ball),
          hough(c.hough, frontEnd.geometry(), ball, candidatePrefilterFor(c)),
          opencvOptions(speckFreeHoughOptions(c.opencvHough, c.edges))
    {
    }

    Config config;
    FrameDenoiser denoiser;
    FrontEnd frontEnd;
    DistanceMap distanceMap;
    BallModel ball;
    SpecificHough hough;  // holds references to frontEnd's geometry and to ball
    OpenCvHough opencvHough;
    OpenCvHoughOptions opencvOptions;  // config.opencvHough with opencv_hough.drop_specks applied
    cv::Mat binary;
    cv::Mat edges;
    const FrameColour* colour = nullptr;  // the frame being processed, for validation
    bool explainRejections = false;       // setExplainRejections
    bool listEveryRefusal = false;        // setListEveryRefusal

    const Geometry& geometry() const { return frontEnd.geometry(); }

    // Validates candidates [first, end) (end 0: to the last).
    void validateFrom(std::size_t first, PipelineResult& r, std::size_t end = 0)
    {
        if (end == 0) end = r.candidates.size();
        for (std::size_t i = first; i < end; ++i)
            validateCandidate(r.candidates[i], r.classes, edges, geometry(), ball, config.validation, colour,
                              frontEnd.roles(), !explainRejections);
    }

    // Thesis 4.1: candidates from the specific Hough transform, validated.
    void searchSpecific(PipelineResult& r, Stopwatch& clock)
    {
        hough.setListEveryRefusal(listEveryRefusal);
        hough.process(edges, binary, r.candidates, r.classes, colour);
        r.hough = hough.stats();
        r.timings.houghMs += clock.lap();
        // The prefilter's listed refusals (and with listEveryRefusal the unlisted ones) come last
        // and are already judged; only the listed ones get a second look, so listing every one
        // changes no verdict.
        const std::size_t listed = std::size_t(r.hough.prefilterListed);
        const std::size_t judged = r.candidates.size() - listed - std::size_t(r.hough.prefilterUnlisted);
        if (judged > 0) validateFrom(0, r, judged);
        recentreOnFits(r.candidates, judged, r.classes, edges, geometry(), ball, config.validation, colour,
                       frontEnd.roles(), !explainRejections);
        if (colour && config.validation.recentreRefused > 0) {
            const RecentreCounts n = recentreRefusals(r.candidates, judged, judged + listed, binary, r.classes, edges,
                                                      geometry(), ball, config.validation, *colour, frontEnd.roles());
            r.hough.recentreTried = n.tried;
            r.hough.recentred = n.kept;
            r.hough.prefilterListed -= n.kept;
        }
        r.timings.validationMs += clock.lap();
    }

    // Thesis 4.2: candidates from cv::HoughCircles, appended and validated.
    void searchOpenCv(PipelineResult& r, Stopwatch& clock)
    {
        const std::size_t first = r.candidates.size();
        opencvHough.process(frontEnd.edgeSource(binary), opencvOptions, geometry(), ball, r.candidates);
        r.timings.houghMs += clock.lap();
        validateFrom(first, r);
        r.timings.validationMs += clock.lap();
    }

    // Thesis 4.3: which searches run; combined tries OpenCV only when the specific one fails
    // (or always, its circles joining the ranking, with opencv_hough.join_ranking).
    void searchBall(PipelineResult& r, Stopwatch& clock)
    {
        const Algorithm alg = config.algorithm;
        if (alg == Algorithm::Specific || alg == Algorithm::Combined) searchSpecific(r, clock);
        if (alg == Algorithm::OpenCv) {
            searchOpenCv(r, clock);
        } else if (alg == Algorithm::Combined && (config.opencvHough.joinRanking || !anyValid(r.candidates))) {
            // The frame's edge count, known before HoughCircles runs, bounds its time.
            const int cap = config.opencvHough.maxEdgePixels;
            r.opencvSkipped = cap > 0 && r.hough.edgePixels > cap;
            if (!r.opencvSkipped) searchOpenCv(r, clock);
        }
    }

    void fillStageImages(const cv::Mat& frame, PixelFormat format, PipelineResult& r) const
    {
        StageImages& s = r.stages;
        if (format == PixelFormat::Bgr8)
            frame.copyTo(s.acquired);
        else
            convertUyvyToBgr(frame, s.acquired);
        paintSegmented(r.classes, geometry().usedMask(), config.colors.classes, s.segmented);
        frontEnd.edgeSource(binary).copyTo(s.grayscale);
        edges.copyTo(s.edges);
        paintVotes(hough.sums(), s.hough);
    }
};

Pipeline::Pipeline(const Config& config) { setConfig(config); }
Pipeline::~Pipeline() = default;

void Pipeline::setConfig(const Config& config)
{
    const auto problems = checkConfig(config);
    if (!problems.empty()) throw std::invalid_argument(problems.front().toString());
    auto built = std::make_unique<Impl>(config);  // only a fully built pipeline replaces the old one
    built->explainRejections = impl_ && impl_->explainRejections;
    built->listEveryRefusal = impl_ && impl_->listEveryRefusal;
    impl_ = std::move(built);
}

const Config& Pipeline::config() const { return impl_->config; }

void Pipeline::setExplainRejections(bool on) { impl_->explainRejections = on; }

void Pipeline::setListEveryRefusal(bool on) { impl_->listEveryRefusal = on; }

void Pipeline::reset() {}

void Pipeline::process(const cv::Mat& frame, PixelFormat format, PipelineResult& r, bool wantStageImages)
{
    Impl& p = *impl_;
    r.error = frameProblem(frame, format, p.geometry().imageSize());
    r.candidates.clear();
    r.detection = BallDetection{};
    r.timings = StageTimings{};
    r.hough = HoughStats{};
    r.opencvSkipped = false;
    if (!r.error.empty()) return;

    Stopwatch clock;
    const cv::Mat& input = p.denoiser.apply(frame, format, p.geometry().spans());
    r.frameNoise = p.denoiser.lastNoise();
    r.denoised = p.denoiser.lastBlurred();
    const double denoiseMs = clock.lap();
    p.frontEnd.process(input, format, r.classes, p.binary, p.edges, &r.timings);
    clock.lap();  // the front end timed its own stages
    r.timings.segmentMs += denoiseMs;  // the blur prepares segmentation
    const FrameColour colour(input, format);
    p.colour = &colour;
    p.searchBall(r, clock);
    p.colour = nullptr;
    const int best = chooseCandidate(r.candidates, p.config.hough.rankByScore);
    if (best >= 0)
        r.detection = detectionOf(r.candidates[std::size_t(best)], best, p.config.geometry, p.distanceMap);
    r.timings.totalMs = clock.total();

    if (wantStageImages) p.fillStageImages(frame, format, r);
}

}  // namespace omnitune
