#pragma once
// omnitune-eval --compare A.yml B.yml: both configs over one session, side by side (detections,
// detection ratio and false positives with truth), then the frames where they differ. The same
// calib function as the window's "apply to whole session" (calib/eval/ConfigComparisonRun.h).
#include "app/CommandLine.h"
#include "calib/eval/Evaluation.h"

#include <string>
#include <vector>

namespace omnitune {

// The arguments with "--compare A B" spelled "--compare A --compare B", so that the shared
// parser (one value per option, "compare" repeatable) reads both files.
class CompareArguments {
public:
    CompareArguments(int argc, const char* const* argv);
    int argc() const { return int(pointers_.size()); }
    const char* const* argv() const { return pointers_.data(); }

private:
    std::vector<std::string> args_;
    std::vector<const char*> pointers_;
};

// Runs the comparison the parsed arguments ask for and prints it on stdout; the exit code.
int runEvalCompare(const CommandLine& cl, const EvaluationOptions& options);

}  // namespace omnitune
