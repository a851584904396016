#include "calib/eval/QualityRun.h"

#include "core/ConfigWriter.h"
#include "core/Pipeline.h"
#include "core/Stopwatch.h"

#include <algorithm>
#include <cmath>
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
    frames += o.frames;
    withBall += o.withBall;
    correct += o.correct;
    falsePositives += o.falsePositives;
    rangeErrorsM.insert(rangeErrorsM.end(), o.rangeErrorsM.begin(), o.rangeErrorsM.end());
    timesMs.insert(timesMs.end(), o.timesMs.begin(), o.timesMs.end());
}

double QualityTally::detectionPct() const { return withBall ? 100.0 * correct / withBall : 0.0; }
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

QualityRun runQuality(const std::vector<OpticsCell>& cells, const std::vector<QualityVariant>& variants,
                      const Config& base, const QualityRunOptions& options, Progress* progress)
{
    QualityRun run;
    run.variants = variants;
    std::vector<std::map<std::string, std::unique_ptr<Pipeline>>> pipelines(variants.size());
    PipelineResult result;
    for (std::size_t ci = 0; ci < cells.size(); ++ci) {
        if (progress && progress->isCancelRequested()) break;
        const OpticsCell& cell = cells[ci];
        Stopwatch renderClock;
        const OpticsCellFrames rendered = renderCell(cell, base);
        run.renderMs += renderClock.total();
        QualityCellResult cr;
        cr.cell = cell;
        cr.name = opticsCellName(cell);
        for (std::size_t vi = 0; vi < variants.size(); ++vi) {
            const QualityVariant& variant = variants[vi];
            Config config = rendered.fittedConfig;
            config.algorithm = variant.algorithm;
            for (const ConfigOverride& o : variant.overrides)
                if (auto why = applyConfigOverride(config, o)) throw std::invalid_argument(variant.name + ": " + *why);
            auto& slot = pipelines[vi][configKey(config)];
            try {
                if (!slot) slot = std::make_unique<Pipeline>(config);
            } catch (const std::exception& e) {
                throw std::invalid_argument(cr.name + " (" + variant.name + "): the fitted config is refused: " + e.what());
            }
            QualityTally tally;
            for (std::size_t f = 0; f < rendered.frames.size(); ++f) {
                const auto t = rendered.truth.find(int(f));
                if (t == rendered.truth.end()) continue;
                slot->process(rendered.frames[f], PixelFormat::Bgr8, result);
                const FrameOutcome outcome = outcomeOf(int(f), result);
                const TruthRow& truth = t->second;
                const TruthVerdict verdict = judge(outcome, &truth, options.evaluation);
                ++tally.frames;
                if (outcome.processed) tally.timesMs.push_back(outcome.timeMs);
                tally.falsePositives += verdict == TruthVerdict::FalsePositive;
                if (!truth.ballVisible) continue;
                ++tally.withBall;
                if (verdict != TruthVerdict::Correct) continue;
                ++tally.correct;
                const double trueRange = std::hypot(truth.xM, truth.yM);
                if (trueRange <= options.rangeWithinM)
                    tally.rangeErrorsM.push_back(std::hypot(outcome.detection.xM, outcome.detection.yM) - trueRange);
            }
            cr.tallies.push_back(std::move(tally));
        }
        run.cells.push_back(std::move(cr));
        if (progress) progress->update(100.0 * double(ci + 1) / double(cells.size()));
    }
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
