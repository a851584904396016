// omnitune-eval: the thesis' Table 5.x for recorded sessions with truth.csv, one row per
// session and algorithm.
#include "calib/eval/BatchRun.h"
#include "app/CommandLine.h"
#include "app/EvalCompare.h"
#include "app/QualityTool.h"
#include "calib/eval/Evaluation.h"
#include "calib/session/SessionReader.h"
#include "calib/source/SessionSource.h"
#include "app/StderrProgress.h"
#include "app/ToolConfig.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

using namespace omnitune;

namespace {

const std::vector<OptionSpec> kSessionOptions = {
    {"session", true, true, "DIR   a session with truth.csv; repeat for several (one row each)"},
    {"config", true, false, "FILE  detector config (default: each session's config.yml)"},
    {"algorithm", true, false, "A     specific | opencv | combined | all (default: the config's)"},
    {"format", true, false, "F     md (default) or csv"},
    {"max-error", true, false, "M     metres beyond which a detection is a false positive (default 0.5)"},
    {"compare", true, true, "A B   two configs over one session, side by side, and the frames that changed"},
    {"help", false, false, "      this text"},
};

std::vector<OptionSpec> allOptions()
{
    std::vector<OptionSpec> o = kSessionOptions;
    for (OptionSpec& q : qualityToolOptions()) o.push_back(std::move(q));
    return o;
}
const std::vector<OptionSpec> kOptions = allOptions();

int fail(const std::string& why)
{
    std::cerr << "omnitune-eval: " << why << "\n";
    return 1;
}

// Why a session gives no truth to evaluate against: no truth.csv, or one without a usable row.
std::string whyNoTruth(const SessionReader& session)
{
    const std::string path = (std::filesystem::path(session.folder()) / kSessionTruthFile).string();
    if (!session.hasTruthFile())
        return session.folder() + " has no truth.csv (mark the ball first, or use omnitune-detect)";
    std::string reasons;
    int shown = 0;
    for (const SessionIssue& w : session.warnings())
        if (w.file == path && shown++ < 3) reasons += (reasons.empty() ? "" : "; ") + w.toString();
    return path + " holds " + std::to_string(session.truthRowsInFile()) +
           " rows but none is usable" + (reasons.empty() ? "" : ": " + reasons);
}

}  // namespace

int main(int argc, char** argv)
{
    quietOpenCvLogs();
    const CompareArguments args(argc, argv);  // "--compare A B": two values
    const CommandLine cl = parseCommandLine(args.argc(), args.argv(), kOptions);
    if (cl.has("help")) {
        std::cout << usageText("omnitune-eval", "Evaluates the detector against sessions' ground truth (thesis ch. 5).",
                               kOptions);
        return 0;
    }
    if (!cl.error.empty()) return fail(cl.error + " (see --help)");
    if (cl.has("quality-matrix")) return runQualityTool(cl);
    if (!cl.has("session")) return fail("--session is required (see --help)");
    const std::string format = cl.value("format").value_or("md");
    if (format != "md" && format != "csv") return fail("--format must be md or csv, not '" + format + "'");
    EvaluationOptions options;
    if (auto m = cl.value("max-error")) {
        const auto v = parseDouble(*m);
        if (!v || *v <= 0) return fail("--max-error must be a positive number of metres, not '" + *m + "'");
        options.maxErrorM = *v;
    }
    if (cl.has("compare")) return runEvalCompare(cl, options);
    std::vector<std::string> algorithms;
    const std::string algorithm = cl.value("algorithm").value_or("");
    if (algorithm == "all")
        algorithms = {"specific", "opencv", "combined"};
    else
        algorithms = {algorithm};

    std::vector<EvaluationRow> rows;
    bool allEvaluated = true;
    for (const std::string& dir : cl.all("session")) {
        SessionOpen opened = SessionReader::open(dir);
        if (!opened.ok()) return fail(opened.error->toString());
        for (const auto& w : opened.reader->warnings()) std::cerr << "warning: " << w.toString() << "\n";
        if (opened.reader->truth().empty()) return fail(whyNoTruth(*opened.reader));
        const auto truth = opened.reader->truth();
        const std::string name = std::filesystem::path(dir).filename().string();
        for (const std::string& a : algorithms) {
            std::string error;
            const auto config = loadToolConfig(cl.value("config"), dir, a.empty() ? std::nullopt : std::optional(a), error);
            if (!config) return fail(error);
            SessionSource source(*opened.reader);
            std::vector<FrameOutcome> outcomes;
            std::string firstFailure;
            try {
                Pipeline pipeline(*config);
                StderrProgress progress("omnitune-eval " + name + " " + std::string(algorithmName(config->algorithm)));
                runBatch(source, pipeline,
                         [&](int index, const Frame*, const PipelineResult& r) {
                             if (!r.ok()) std::cerr << "frame " << index << " skipped: " << r.error << "\n";
                             if (!r.ok() && firstFailure.empty()) firstFailure = r.error;
                             outcomes.push_back(outcomeOf(index, r));
                         },
                         &progress);
            } catch (const std::exception& e) {
                return fail(e.what());
            }
            EvaluationRow row = evaluate(outcomes, truth, options);
            row.session = name;
            row.algorithm = std::string(algorithmName(config->algorithm));
            // A row of zeros would read as "the detector found nothing": say what went wrong instead.
            if (row.frames == 0 || row.annotated == 0) {
                std::cerr << "omnitune-eval: " << dir << " (" << row.algorithm << "): nothing evaluated: "
                          << (row.frames == 0 ? "none of its " + std::to_string(outcomes.size()) +
                                                    " frames could be processed" +
                                                    (firstFailure.empty() ? "" : " (first: " + firstFailure + ")")
                                              : "no processed frame has a truth row")
                          << "\n";
                allEvaluated = false;
                continue;
            }
            rows.push_back(row);
        }
    }
    if (!rows.empty()) {
        errno = 0;
        std::cout << (format == "md" ? evaluationMarkdown(rows) : evaluationCsv(rows)) << std::flush;
        if (!std::cout)
            return fail(std::string("writing the table to standard output failed") +
                        (errno ? std::string(": ") + std::strerror(errno) : std::string()));
    }
    if (!allEvaluated) return 1;
    return 0;
}
