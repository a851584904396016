// Per-stage and whole-pipeline timings on simulated 640x480 omnidirectional frames, each
// beside cv::HoughCircles with the thesis' parameters on the same frames (see RatioReporter).
// The optics simulator's hardest frames (dim light with noise + blur, rods, robots and feet)
// have their own reference: cv::HoughCircles on those frames' binary images.
// Run: scripts/bench  (numbers and machine in docs/performance.md)
#include "RatioReporter.h"

#include "calib/eval/ConfigOverride.h"
#include "calib/sim/BallKind.h"
#include "calib/sim/SceneSimulator.h"
#include "calib/sim/Tour.h"
#include "calib/sim/optics/OpticsCell.h"
#include "core/Stopwatch.h"
#include "core/FrontEnd.h"
#include "core/Pipeline.h"

#include <opencv2/imgproc.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

namespace {

using namespace omnitune;

// OMNITUNE_BENCH_SET="hough.blob_seeds=false;hough.masked_centres=false" runs every benchmark
// with those keys set, so a deviation from the thesis is timed both ways on the same frames.
// A bad key or value ends the run with the reason (a silent typo would time the defaults).
void applyBenchOverrides(Config& config)
{
    const char* env = std::getenv("OMNITUNE_BENCH_SET");
    if (!env) return;
    std::istringstream in(env);
    std::string item;
    while (std::getline(in, item, ';')) {
        if (item.empty()) continue;
        const auto eq = item.find('=');
        const ConfigOverride o{item.substr(0, eq), eq == std::string::npos ? std::string() : item.substr(eq + 1), {}};
        if (const auto why = applyConfigOverride(config, o)) {
            std::fprintf(stderr, "OMNITUNE_BENCH_SET: %s: %s\n", item.c_str(), why->c_str());
            std::exit(2);
        }
    }
}

Config benchConfig()
{
    Config config;
    applyBenchOverrides(config);
    return config;
}

// The frames every benchmark shares: a tour around each of the five balls, and the stages
// before the Hough transform computed once (by the pipeline's own front end) so that each
// stage is timed on its own input.
struct Frames {
    Config config;
    std::vector<cv::Mat> bgr;
    std::vector<cv::Mat> classes;
    std::vector<cv::Mat> binary;
    std::vector<cv::Mat> edges;
    FrontEnd frontEnd;
    const Geometry& geometry;
    BallModel ball;

    Frames() : config(benchConfig()), frontEnd(config), geometry(frontEnd.geometry()), ball(config.ball)
    {
        const SceneSimulator sim(config);
        for (BallKind kind : kAllBallKinds) {
            TourOptions tour;
            tour.frames = 8;
            tour.ball = kind;
            for (const SceneOptions& scene : makeTour(tour)) bgr.push_back(sim.render(scene));
        }
        for (const cv::Mat& f : bgr) {
            cv::Mat c;
            cv::Mat b;
            cv::Mat e;
            frontEnd.process(f, PixelFormat::Bgr8, c, b, e);
            classes.push_back(c);
            binary.push_back(b);
            edges.push_back(e);
        }
    }
};

const Frames& frames()
{
    static const Frames f;
    return f;
}

void setFrames(benchmark::State& state)
{
    state.SetItemsProcessed(state.iterations());
    state.counters["frames"] = double(frames().bgr.size());
}

// The reference: cv::HoughCircles exactly as the thesis' OpenCV path calls it.
void BM_CvHoughCircles(benchmark::State& state)
{
    const auto& f = frames();
    const OpenCvHoughOptions o;
    std::vector<cv::Vec3f> circles;
    std::size_t i = 0;
    for (auto _ : state) {
        cv::HoughCircles(f.binary[i++ % f.binary.size()], circles, cv::HOUGH_GRADIENT, o.dp, o.minDist, o.cannyHigh,
                         o.accThreshold, o.minRadius, o.maxRadius);
        benchmark::DoNotOptimize(circles.data());
    }
    setFrames(state);
}

// Segmentation at each LUT resolution; "agreement" is the share of pixels classified as the
// exact (8-bit) table does, so speed and accuracy of the choice show side by side.
void BM_Segment(benchmark::State& state)
{
    const auto& f = frames();
    ColorLutOptions o = f.config.colors;
    o.bits = int(state.range(0));
    const ColorLut lut(o);
    ColorLutOptions exactOptions = o;
    exactOptions.bits = 8;
    const ColorLut exact(exactOptions);
    cv::Mat out(f.bgr[0].size(), CV_8UC1, cv::Scalar(0));
    std::size_t i = 0;
    for (auto _ : state) {
        lut.segment(f.bgr[i++ % f.bgr.size()], PixelFormat::Bgr8, f.geometry.spans(), out);
        benchmark::ClobberMemory();
    }
    double same = 0;
    double total = 0;
    cv::Mat ref(out.size(), CV_8UC1, cv::Scalar(0));
    for (const cv::Mat& img : f.bgr) {
        lut.segment(img, PixelFormat::Bgr8, f.geometry.spans(), out);
        exact.segment(img, PixelFormat::Bgr8, f.geometry.spans(), ref);
        same += double(f.geometry.usedPixels().size()) - cv::countNonZero(out != ref);
        total += double(f.geometry.usedPixels().size());
    }
    state.counters["agreement_pct"] = 100.0 * same / total;
    state.counters["table_KiB"] = double(std::size_t(1) << (3 * o.bits)) / 1024.0;
    setFrames(state);
}

void BM_Binary(benchmark::State& state)
{
    const auto& f = frames();
    cv::Mat out;
    std::size_t i = 0;
    for (auto _ : state) makeBinary(f.classes[i++ % f.classes.size()], f.geometry, out);
    setFrames(state);
}

void BM_Canny(benchmark::State& state)
{
    const auto& f = frames();
    CannyDetector canny;
    cv::Mat out;
    std::size_t i = 0;
    for (auto _ : state) canny.detect(f.binary[i++ % f.binary.size()], f.config.edges, out);
    setFrames(state);
}

void BM_CvCanny(benchmark::State& state)
{
    const auto& f = frames();
    cv::Mat out;
    std::size_t i = 0;
    for (auto _ : state) cv::Canny(f.binary[i++ % f.binary.size()], out, f.config.edges.cannyLow, f.config.edges.cannyHigh);
    setFrames(state);
}

void BM_SpecificHough(benchmark::State& state)
{
    const auto& f = frames();
    SpecificHough hough(f.config.hough, f.geometry, f.ball);
    std::vector<BallCandidate> cands;
    cands.reserve(16);
    std::size_t i = 0;
    for (auto _ : state) {
        cands.clear();
        const std::size_t k = i++ % f.edges.size();
        hough.process(f.edges[k], f.binary[k], cands);
    }
    setFrames(state);
}

void BM_Validation(benchmark::State& state)
{
    const auto& f = frames();
    SpecificHough hough(f.config.hough, f.geometry, f.ball);
    std::vector<std::vector<BallCandidate>> perFrame;
    for (std::size_t k = 0; k < f.edges.size(); ++k) {
        perFrame.emplace_back();
        hough.process(f.edges[k], f.binary[k], perFrame.back());
    }
    std::size_t i = 0;
    for (auto _ : state) {
        const std::size_t k = i++ % perFrame.size();
        for (BallCandidate c : perFrame[k]) {
            validateCandidate(c, f.classes[k], f.edges[k], f.geometry, f.ball, f.config.validation);
            benchmark::DoNotOptimize(c.scores);
        }
    }
    setFrames(state);
}

void BM_Pipeline(benchmark::State& state)
{
    const auto& f = frames();
    Config c = f.config;
    c.algorithm = static_cast<Algorithm>(state.range(0));
    Pipeline pipeline(c);
    PipelineResult r;
    std::size_t i = 0;
    int found = 0;
    for (auto _ : state) {
        pipeline.process(f.bgr[i++ % f.bgr.size()], PixelFormat::Bgr8, r);
        found += r.detection.found;
    }
    state.SetLabel(std::string(algorithmName(c.algorithm)));
    state.counters["found_pct"] = 100.0 * found / double(state.iterations());
    setFrames(state);
}


// The optics simulator's hardest cells (issue 9: dim light, sensor noise + motion blur, rods
// and occlusion, robots + feet + head shadow), every ball kind, 640x480 through the hyperbolic
// mirror, each with its own fitted config; the binary image cv::HoughCircles gets is the
// pipeline's own (its grayscale stage), so the reference sees what the OpenCV path sees.
struct HardFrames {
    struct Cell {
        std::unique_ptr<Pipeline> specific, opencv, combined;
        std::vector<cv::Mat> bgr;
        std::vector<cv::Mat> binary;
    };
    std::vector<Cell> cells;
    std::size_t frames = 0;

    HardFrames()
    {
        for (OpticsDistractors d : {OpticsDistractors::NoiseBlur, OpticsDistractors::RodsOcclusion,
                                    OpticsDistractors::RobotsFeetShadow})
            for (BallKind kind : kExtendedBallKinds) {
                OpticsCell spec;
                spec.ball = kind;
                spec.light = OpticsLight::Dim;
                spec.distractors = d;
                spec.frames = 4;
                spec.seed = 4242u + unsigned(cells.size());
                OpticsCellFrames rendered = renderCell(spec);
                Cell cell;
                Config c = rendered.fittedConfig;
                applyBenchOverrides(c);
                c.algorithm = Algorithm::Specific;
                cell.specific = std::make_unique<Pipeline>(c);
                c.algorithm = Algorithm::OpenCv;
                cell.opencv = std::make_unique<Pipeline>(c);
                c.algorithm = Algorithm::Combined;
                cell.combined = std::make_unique<Pipeline>(c);
                PipelineResult r;
                for (const cv::Mat& f : rendered.frames) {
                    cell.specific->process(f, PixelFormat::Bgr8, r, true);
                    cell.bgr.push_back(f);
                    cell.binary.push_back(r.stages.grayscale.clone());
                    ++frames;
                }
                cells.push_back(std::move(cell));
            }
    }

    // The k-th frame over all cells, round robin.
    template <class F>
    void at(std::size_t k, F&& f) const
    {
        for (const Cell& c : cells) {
            if (k < c.bgr.size()) return f(c, k);
            k -= c.bgr.size();
        }
    }
};

const HardFrames& hardFrames()
{
    static const HardFrames f;
    return f;
}

// One iteration is a pass over every hard frame (each benchmark sees the same frames, however
// few iterations a slow one gets); RatioReporter divides by "frames_per_iteration".
void BM_HardCvHoughCircles(benchmark::State& state)
{
    const auto& f = hardFrames();
    const OpenCvHoughOptions o;
    std::vector<cv::Vec3f> circles;
    for (auto _ : state)
        for (std::size_t i = 0; i < f.frames; ++i)
            f.at(i, [&](const HardFrames::Cell& c, std::size_t k) {
                cv::HoughCircles(c.binary[k], circles, cv::HOUGH_GRADIENT, o.dp, o.minDist, o.cannyHigh, o.accThreshold,
                                 o.minRadius, o.maxRadius);
                benchmark::DoNotOptimize(circles.data());
            });
    state.SetItemsProcessed(state.iterations() * std::int64_t(f.frames));
    state.counters["frames_per_iteration"] = double(f.frames);
}

// Also the per-frame p50 and p99 (issue 9: p99 <= 10 ms on one core for specific and combined).
void BM_HardPipeline(benchmark::State& state)
{
    const auto& f = hardFrames();
    const auto algorithm = static_cast<Algorithm>(state.range(0));
    PipelineResult r;
    std::vector<double> ms;
    int found = 0;
    int skipped = 0;  // combined: frames whose OpenCV search opencv_hough.max_edge_pixels skipped
    for (auto _ : state)
        for (std::size_t i = 0; i < f.frames; ++i)
            f.at(i, [&](const HardFrames::Cell& c, std::size_t k) {
                Pipeline& p = algorithm == Algorithm::Specific ? *c.specific
                              : algorithm == Algorithm::OpenCv ? *c.opencv
                                                               : *c.combined;
                Stopwatch clock;
                p.process(c.bgr[k], PixelFormat::Bgr8, r);
                ms.push_back(clock.total());
                found += r.detection.found;
                skipped += r.opencvSkipped;
            });
    std::sort(ms.begin(), ms.end());
    auto percentile = [&](double p) {
        return ms.empty() ? 0.0 : ms[std::min(ms.size() - 1, std::size_t(p / 100.0 * double(ms.size())))];
    };
    state.SetLabel(std::string(algorithmName(algorithm)));
    state.counters["p50_ms"] = percentile(50);
    state.counters["p99_ms"] = percentile(99);
    state.counters["found_pct"] = ms.empty() ? 0.0 : 100.0 * found / double(ms.size());
    state.counters["opencv_skipped_pct"] = ms.empty() ? 0.0 : 100.0 * skipped / double(ms.size());
    state.SetItemsProcessed(state.iterations() * std::int64_t(f.frames));
    state.counters["frames_per_iteration"] = double(f.frames);
}

}  // namespace

// Segmentation with the thesis' fixed black (0) and with black relative to the carpet (1):
// the cost of the per-frame carpet histogram and remap.
void BM_SegmentRelativeBlack(benchmark::State& state)
{
    const auto& f = frames();
    ColorLutOptions o = f.config.colors;
    o.blackRelative = state.range(0) != 0;
    const ColorLut lut(o);
    cv::Mat out(f.bgr[0].size(), CV_8UC1, cv::Scalar(0));
    std::size_t i = 0;
    for (auto _ : state) {
        lut.segment(f.bgr[i++ % f.bgr.size()], PixelFormat::Bgr8, f.geometry.spans(), out);
        benchmark::ClobberMemory();
    }
    setFrames(state);
}

BENCHMARK(BM_CvHoughCircles)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Segment)->DenseRange(4, 8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SegmentRelativeBlack)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Binary)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Canny)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CvCanny)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpecificHough)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Validation)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Pipeline)
    ->Arg(int(omnitune::Algorithm::Specific))
    ->Arg(int(omnitune::Algorithm::OpenCv))
    ->Arg(int(omnitune::Algorithm::Combined))
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HardCvHoughCircles)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HardPipeline)
    ->Arg(int(omnitune::Algorithm::Specific))
    ->Arg(int(omnitune::Algorithm::OpenCv))
    ->Arg(int(omnitune::Algorithm::Combined))
    ->Unit(benchmark::kMillisecond);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    // Each family against cv::HoughCircles on its own frames (first matching prefix).
    RatioReporter reporter({{"BM_Hard", "BM_HardCvHoughCircles"}, {"", "BM_CvHoughCircles"}});
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
