#include "calib/eval/ConfigComparisonRun.h"

#include "calib/eval/BatchRun.h"
#include "calib/source/FrameSourceFactory.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"
#include "core/Pipeline.h"

#include <memory>

namespace omnitune {

namespace {

// The saved config's pipeline, or why there is none.
struct SavedPipeline {
    std::unique_ptr<Pipeline> pipeline;
    bool sameAsCurrent = false;
    std::string note;
};

SavedPipeline makeSavedPipeline(const ConfigComparisonRequest& request)
{
    SavedPipeline saved;
    const std::string& path = request.savedConfigPath;
    std::optional<Config> config = request.savedConfig;
    if (!config) {
        if (path.empty()) {
            saved.note = "The config has never been saved: there is nothing to compare with, the slider marks "
                         "detections only.";
            return saved;
        }
        ConfigLoad load = loadConfig(path);
        if (!load.ok()) {
            saved.note = "The saved config cannot be loaded, so nothing is compared: " + load.error->toString();
            return saved;
        }
        config = std::move(load.config);
    }
    if (sameDetector(*config, request.current)) {
        saved.sameAsCurrent = true;
        return saved;
    }
    try {
        saved.pipeline = std::make_unique<Pipeline>(*config);
    } catch (const std::exception& e) {
        saved.note = "The saved config " + path + " cannot run, so nothing is compared: " + e.what();
    }
    return saved;
}

void run(const ConfigComparisonRequest& request, ConfigComparisonResult& result, Progress* progress)
{
    result.hasTruth = !request.truth.empty();
    SourceOpen<FrameSource> opened = openFrameSource(request.sourcePath);
    if (!opened.ok()) {
        result.error = opened.error;
        return;
    }
    FrameSource& source = *opened.source;
    std::unique_ptr<Pipeline> current;
    try {
        current = std::make_unique<Pipeline>(request.current);
    } catch (const std::exception& e) {
        result.error = std::string("The current config cannot run: ") + e.what();
        return;
    }
    SavedPipeline saved = makeSavedPipeline(request);
    result.savedIsCurrent = saved.sameAsCurrent;
    result.hasSaved = saved.sameAsCurrent || saved.pipeline;
    result.savedNote = saved.note;

    result.total = source.frameCount();
    if (progress) progress->update(0.0);
    PipelineResult savedRun;
    const BatchSummary summary = runBatch(
        source, *current,
        [&](int index, const Frame* frame, const PipelineResult& r) {
            result.current.push_back(outcomeOf(index, r));
            if (!r.ok() && result.firstFrameError.empty())
                result.firstFrameError = "frame " + std::to_string(index) + ": " + r.error;
            if (!saved.pipeline) return;
            if (!frame) {
                result.saved.push_back(outcomeOf(index, r));  // unreadable for both
                return;
            }
            try {
                saved.pipeline->process(frame->image, frame->format, savedRun, false);
            } catch (const std::exception& e) {
                savedRun = PipelineResult{};
                savedRun.error = e.what();
            }
            result.saved.push_back(outcomeOf(index, savedRun));
        },
        progress);
    result.visited = summary.frames;
    result.cancelled = summary.cancelled;
    if (saved.sameAsCurrent) result.saved = result.current;

    result.currentRow = evaluate(result.current, request.truth, request.evaluation);
    for (const FrameOutcome& o : result.current) {
        const auto t = request.truth.find(o.frame);
        const TruthVerdict v = judge(o, t == request.truth.end() ? nullptr : &t->second, request.evaluation);
        if (v == TruthVerdict::FalsePositive) result.falsePositiveFrames.push_back(o.frame);
        if (v == TruthVerdict::Missed) result.missedFrames.push_back(o.frame);
    }
    if (result.hasSaved) {
        result.savedRow = evaluate(result.saved, request.truth, request.evaluation);
        result.comparison = compareSessions(result.current, result.saved, request.comparison);
    }
}

}  // namespace

bool sameDetector(const Config& a, const Config& b)
{
    if (serializeConfig(a) != serializeConfig(b)) return false;
    if (a.mask.empty() || b.mask.empty()) return a.mask.empty() == b.mask.empty();
    return a.mask.size() == b.mask.size() && a.mask.type() == b.mask.type() && cv::norm(a.mask, b.mask, cv::NORM_INF) == 0;
}

void runConfigComparison(const ConfigComparisonRequest& request, ConfigComparisonResult& out, Progress* progress)
{
    out = ConfigComparisonResult{};
    try {
        run(request, out, progress);
    } catch (const std::exception& e) {  // nothing escapes: a thread runs this
        out.error = std::string("The run stopped: ") + e.what();
    }
}

}  // namespace omnitune
