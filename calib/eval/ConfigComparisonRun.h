#pragma once
// Two configs over every frame of one source: the config being tuned ("current") and another
// one, usually the saved file ("saved"). Each frame is read once and both pipelines run on it,
// so a cancelled run still compares the same frames. Then both are evaluated against the truth
// (when there is any) and compared frame by frame. The GUI's "apply to whole session" runs it
// in a thread; `omnitune-eval --compare A B` runs it on the command line.
#include "calib/eval/Evaluation.h"
#include "calib/eval/SessionComparison.h"
#include "calib/session/TruthCsv.h"
#include "core/Config.h"
#include "core/Progress.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct ConfigComparisonRequest {
    std::string sourcePath;              // session folder, video, image folder or glob
    Config current;                      // the config being tuned
    std::string savedConfigPath;         // the other config's file; empty: nothing to compare with
    std::optional<Config> savedConfig;   // already loaded (the path then only names it)
    std::map<int, TruthRow> truth;       // ground truth by frame; may be empty
    ComparisonOptions comparison;
    EvaluationOptions evaluation;
};

struct ConfigComparisonResult {
    std::string error;            // nothing ran (the source or the current config is unusable)
    int total = 0;                // frames in the source; -1 when the source does not know
    int visited = 0;              // frames visited (all of them unless cancelled)
    bool cancelled = false;       // stopped early: everything below covers the visited frames
    std::string firstFrameError;  // the first frame that could not be read or processed, if any

    bool hasSaved = false;        // the saved config ran: `saved`, `savedRow`, `comparison` valid
    bool savedIsCurrent = false;  // the saved config is the same (ran once, used twice)
    std::string savedNote;        // why there is no comparison, when hasSaved is false
    bool hasTruth = false;        // truth rows were given: ratios and false positives mean something

    std::vector<FrameOutcome> current;
    std::vector<FrameOutcome> saved;
    EvaluationRow currentRow;
    std::vector<int> falsePositiveFrames;  // the current config's, with truth (judge())
    std::vector<int> missedFrames;
    EvaluationRow savedRow;
    SessionComparison comparison;

    bool ok() const { return error.empty(); }
};

// Fills `out` (a fresh result). `out.total` is set before the first progress update, so that a
// progress adapter can turn percents into frames. `progress` may be null; its cancel request
// stops the run before the next frame. Never throws: failures become `error` or notes.
void runConfigComparison(const ConfigComparisonRequest& request, ConfigComparisonResult& out,
                         Progress* progress = nullptr);

// The same detector: equal saved text and equal masks (running it again repeats the numbers).
bool sameDetector(const Config& a, const Config& b);

}  // namespace omnitune
