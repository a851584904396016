#include "calib/eval/QualityRun.h"

#include "calib/colour/AutoColour.h"
#include "calib/sim/UyvyEncoding.h"

#include "core/ConfigWriter.h"
#include "core/Pipeline.h"
#include "core/PrefilterRefusals.h"
#include "core/Stopwatch.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <map>
#include <memory>
#include <numeric>
#include <stdexcept>

namespace omnitune {

std::vector<QualityVariant> algorithmVariants()
{
    std::vector<QualityVariant> v;
    for (Algorithm a : {Algorithm::Specific, Algorithm::OpenCv, Algorithm::Combined})
        v.push_back({std::string(algorithmName(a)), a, {}});
    return v;
}

std::vector<QualityVariant> deviationVariants(const std::vector<ConfigOverride>& deviations,
                                              const std::vector<Algorithm>& algorithms)
{
    std::vector<QualityVariant> v;
    for (Algorithm a : algorithms) {
        const std::string alg(algorithmName(a));
        for (const ConfigOverride& d : deviations) v.push_back({alg + ", " + overrideLabel(d), a, {d}});
        if (deviations.size() > 1) v.push_back({alg + ", all thesis values", a, deviations});
    }
    return v;
}

void QualityTally::add(const QualityTally& o)
{
    BallFrameTally::add(o);
    frames += o.frames;
    falsePositives += o.falsePositives;
    atHiddenBalls += o.atHiddenBalls;
    rangeErrorsM.insert(rangeErrorsM.end(), o.rangeErrorsM.begin(), o.rangeErrorsM.end());
    timesMs.insert(timesMs.end(), o.timesMs.begin(), o.timesMs.end());
    for (std::size_t i = 0; i < byPlace.size(); ++i) byPlace[i].add(o.byPlace[i]);
    for (std::size_t i = 0; i < falsePositiveKinds.size(); ++i) falsePositiveKinds[i] += o.falsePositiveKinds[i];
}

void BallFrameTally::add(const BallFrameTally& o)
{
    withBall += o.withBall;
    correct += o.correct;
    for (std::size_t i = 0; i < missCauses.size(); ++i) missCauses[i] += o.missCauses[i];
    missesRadiusOff += o.missesRadiusOff;
    missesPrefiltered += o.missesPrefiltered;
}

double BallFrameTally::detectionPct() const { return withBall ? 100.0 * correct / withBall : 0.0; }

double QualityTally::falsePositivePct() const { return frames ? 100.0 * falsePositives / frames : 0.0; }

double QualityTally::rangeBiasCm() const
{
    if (rangeErrorsM.empty()) return 0.0;
    return 100.0 * std::accumulate(rangeErrorsM.begin(), rangeErrorsM.end(), 0.0) / double(rangeErrorsM.size());
}

double QualityTally::rangeStdCm() const
{
    if (rangeErrorsM.empty()) return 0.0;
    const double mean = rangeBiasCm() / 100.0;
    double ss = 0;
    for (double e : rangeErrorsM) ss += (e - mean) * (e - mean);
    return 100.0 * std::sqrt(ss / double(rangeErrorsM.size()));
}

double QualityTally::timePercentileMs(double p) const
{
    if (timesMs.empty()) return 0.0;
    std::vector<double> sorted = timesMs;
    std::sort(sorted.begin(), sorted.end());
    const double rank = std::ceil(std::clamp(p, 0.0, 100.0) / 100.0 * double(sorted.size()));
    const std::size_t i = std::size_t(std::max(1.0, rank)) - 1;
    return sorted[std::min(i, sorted.size() - 1)];
}

namespace {

// Pipelines are expensive to set up (colour table, geometry, Hough offsets) and cells of one
// camera share their fitted config: keep one per (variant, config) and reuse it.
std::string configKey(const Config& c)
{
    std::string key = serializeConfig(c);
    if (!c.mask.empty()) {
        std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the mask's bytes
        for (int y = 0; y < c.mask.rows; ++y) {
            const uchar* row = c.mask.ptr<uchar>(y);
            for (std::size_t x = 0; x < std::size_t(c.mask.cols) * c.mask.elemSize(); ++x) h = (h ^ row[x]) * 1099511628211ull;
        }
        key += "\nmask " + std::to_string(c.mask.cols) + "x" + std::to_string(c.mask.rows) + " " + std::to_string(h);
    }
    return key;
}

}  // namespace

namespace {

// Mixed into a cell's seed for its colour-calibration frames: other ball positions and noise.
constexpr unsigned kCalibrationSeedSalt = 0x5eedc01u;

// One thread's share of a run: its own pipelines, one per (variant, config).
class CellRunner {
public:
    CellRunner(const std::vector<QualityVariant>& variants, const Config& base, const QualityRunOptions& options)
        : variants_(variants), base_(base), options_(options), pipelines_(variants.size())
    {
    }

    QualityCellResult run(const OpticsCell& cell, double& renderMs)
    {
        Stopwatch renderClock;
        OpticsCellFrames rendered = renderCell(cell, base_);
        if (options_.autoColourFrames > 0) autoColours(cell, rendered);
        renderMs += renderClock.total();
        QualityCellResult cr;
        cr.cell = cell;
        cr.name = opticsCellName(cell);
        for (std::size_t vi = 0; vi < variants_.size(); ++vi) {
            const QualityVariant& variant = variants_[vi];
            Config config = rendered.fittedConfig;
            config.algorithm = variant.algorithm;
            for (const ConfigOverride& o : variant.overrides)
                if (auto why = applyConfigOverride(config, o)) throw std::invalid_argument(variant.name + ": " + *why);
            auto& slot = pipelines_[vi][configKey(config)];
            try {
                if (!slot) {
                    slot = std::make_unique<Pipeline>(config);
                    const bool explain = options_.recordMisses || options_.explainRejections;
                    slot->setExplainRejections(explain);
                    slot->setListEveryRefusal(explain);
                }
            } catch (const std::exception& e) {
                throw std::invalid_argument(cr.name + " (" + variant.name + "): the fitted config is refused: " + e.what());
            }
            cr.tallies.push_back(judgeFrames(*slot, config, rendered));
        }
        return cr;
    }

private:
    // QualityRunOptions::autoColourFrames: the cell's colours from frames of its own field and
    // light (another seed). A calibration that fails keeps the default colours, as a user would.
    void autoColours(const OpticsCell& cell, OpticsCellFrames& rendered) const
    {
        OpticsCell calibration = cell;
        calibration.seed = cell.seed ^ kCalibrationSeedSalt;
        calibration.frames = options_.autoColourFrames;
        const OpticsCellFrames frames = renderCell(calibration, base_);
        Config& config = rendered.fittedConfig;
        const AutoColourResult r = autoColour(frames.frames, Geometry(config.geometry, config.mask), config.colors);
        if (r.ok()) config.colors = r.colors;
    }

    QualityTally judgeFrames(Pipeline& pipeline, const Config& config, const OpticsCellFrames& rendered)
    {
        QualityTally tally;
        for (std::size_t f = 0; f < rendered.frames.size(); ++f) {
            const auto t = rendered.truth.find(int(f));
            if (t == rendered.truth.end()) continue;
            if (options_.pixelFormat == PixelFormat::Uyvy) {
                convertBgrToUyvy(rendered.frames[f], uyvy_);
                pipeline.process(uyvy_, PixelFormat::Uyvy, result_);
            } else {
                pipeline.process(rendered.frames[f], PixelFormat::Bgr8, result_);
            }
            const FrameOutcome outcome = outcomeOf(int(f), result_);
            const TruthRow& truth = t->second;
            const auto hidden = rendered.hiddenBalls.find(int(f));
            const TruthVerdict verdict =
                judge(outcome, &truth, options_.evaluation,
                      hidden == rendered.hiddenBalls.end() ? std::nullopt : std::optional<cv::Point2d>(hidden->second));
            ++tally.frames;
            tally.atHiddenBalls += verdict == TruthVerdict::AtHiddenBall;
            if (outcome.processed) tally.timesMs.push_back(outcome.timeMs);
            if (verdict == TruthVerdict::FalsePositive) {
                ++tally.falsePositives;
                const FalsePositiveKind kind = diagnoseFalsePositive(result_, config);
                ++tally.falsePositiveKinds[falsePositiveKindIndex(kind)];
                tally.falsePositiveFrames.push_back(falsePositiveFrame(int(f), truth, kind, rendered.frames[f]));
            }
            if (!truth.ballVisible) continue;
            BallFrameTally ball;
            ++ball.withBall;
            if (verdict == TruthVerdict::Correct) {
                ++ball.correct;
                const double trueRange = std::hypot(truth.xM, truth.yM);
                if (trueRange <= options_.rangeWithinM)
                    tally.rangeErrorsM.push_back(std::hypot(outcome.detection.xM, outcome.detection.yM) - trueRange);
            } else {
                bool radiusOff = false;
                const BallCandidate* atBall = nullptr;
                const MissCause cause = diagnoseMiss(result_, truth, config.validation, &radiusOff, &atBall);
                ++ball.missCauses[std::size_t(cause)];
                ball.missesRadiusOff += radiusOff;
                ball.missesPrefiltered += atBall && prefiltered(*atBall);
                if (options_.recordMisses)
                    tally.missedFrames.push_back(missedFrame(int(f), truth, cause, radiusOff, atBall, rendered.frames[f]));
            }
            countBallFrame(tally, ball, ballPlacesOf(truth, rendered.field, rendered.ballRadiusM));
        }
        return tally;
    }

    // Whether `candidate` (one of result_'s) is a prefilter refusal; only for misses, so the flag
    // vector's allocation stays off the found frames.
    bool prefiltered(const BallCandidate& candidate) const
    {
        const std::size_t index = std::size_t(&candidate - result_.candidates.data());
        return prefilterRefusals(result_).at(index);
    }

    // Adds one ball frame's counts to the tally's totals and to each place it belongs to.
    static void countBallFrame(QualityTally& tally, const BallFrameTally& frame, const std::array<bool, kBallPlaceCount>& places)
    {
        tally.BallFrameTally::add(frame);
        for (std::size_t p = 0; p < kBallPlaceCount; ++p)
            if (places[p]) tally.byPlace[p].add(frame);
    }

    // A false positive's record; rare, so its crop may allocate.
    FalsePositiveFrame falsePositiveFrame(int frame, const TruthRow& truth, FalsePositiveKind kind, const cv::Mat& image) const
    {
        FalsePositiveFrame fp;
        fp.frame = frame;
        fp.ballVisible = truth.ballVisible;
        fp.truthPx = truth.px;
        fp.truthPy = truth.py;
        fp.truthRadiusPx = truth.radiusPx;
        fp.kind = kind;
        const BallDetection& d = result_.detection;
        if (d.candidate >= 0 && d.candidate < int(result_.candidates.size())) fp.chosen = result_.candidates[std::size_t(d.candidate)];
        fp.crop = cropAroundCircle(image, d.px, d.py, d.radiusPx);
        return fp;
    }

    // A missed frame's record (QualityRunOptions::recordMisses only).
    MissedFrame missedFrame(int frame, const TruthRow& truth, MissCause cause, bool radiusOff, const BallCandidate* atBall,
                            const cv::Mat& image) const
    {
        MissedFrame m;
        m.frame = frame;
        m.truthPx = truth.px;
        m.truthPy = truth.py;
        m.truthRadiusPx = truth.radiusPx;
        m.truthRangeM = std::hypot(truth.xM, truth.yM);
        m.cause = cause;
        m.radiusOff = radiusOff;
        m.hasCandidate = atBall != nullptr;
        if (atBall) {
            m.atBall = *atBall;
            m.atBallPrefiltered = prefiltered(*atBall);
        }
        const BallDetection& d = result_.detection;
        m.detected = d.found && d.candidate >= 0 && d.candidate < int(result_.candidates.size());
        if (m.detected) m.chosen = result_.candidates[std::size_t(d.candidate)];
        m.crop = cropAroundCircle(image, truth.px, truth.py, truth.radiusPx);
        return m;
    }

    const std::vector<QualityVariant>& variants_;
    const Config& base_;
    const QualityRunOptions& options_;
    std::vector<std::map<std::string, std::unique_ptr<Pipeline>>> pipelines_;
    PipelineResult result_;
    cv::Mat uyvy_;  // options_.pixelFormat Uyvy: the frame as the detector reads it
};

}  // namespace

QualityRun runQuality(const std::vector<OpticsCell>& cells, const std::vector<QualityVariant>& variants,
                      const Config& base, const QualityRunOptions& options, Progress* progress)
{
    QualityRun run;
    run.variants = variants;
    std::vector<std::optional<QualityCellResult>> results(cells.size());
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::mutex mutex;  // guards done, renderMs, failure and progress
    std::size_t done = 0;
    std::exception_ptr failure;
    auto work = [&] {
        CellRunner runner(variants, base, options);
        double renderMs = 0;
        try {
            for (std::size_t i = next++; i < cells.size() && !stop; i = next++) {
                results[i] = runner.run(cells[i], renderMs);
                const std::lock_guard<std::mutex> lock(mutex);
                ++done;
                if (progress) {
                    progress->update(100.0 * double(done) / double(cells.size()));
                    if (progress->isCancelRequested()) stop = true;
                }
            }
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mutex);
            if (!failure) failure = std::current_exception();
            stop = true;
        }
        const std::lock_guard<std::mutex> lock(mutex);
        run.renderMs += renderMs;
    };
    const int threads = std::max(1, options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(threads, int(cells.size())); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    for (auto& r : results)
        if (r) run.cells.push_back(std::move(*r));
    return run;
}

QualityTally qualityTotal(const QualityRun& run, std::size_t variant, const std::function<bool(const OpticsCell&)>& filter)
{
    QualityTally total;
    for (const QualityCellResult& c : run.cells)
        if (variant < c.tallies.size() && (!filter || filter(c.cell))) total.add(c.tallies[variant]);
    return total;
}

const QualityCellResult* worstQualityCell(const QualityRun& run, std::size_t variant)
{
    const QualityCellResult* worst = nullptr;
    for (const QualityCellResult& c : run.cells) {
        if (variant >= c.tallies.size() || c.tallies[variant].withBall == 0) continue;
        if (!worst || c.tallies[variant].detectionPct() < worst->tallies[variant].detectionPct()) worst = &c;
    }
    return worst;
}

}  // namespace omnitune
