#include "app/EvalCompare.h"

#include "app/StderrProgress.h"
#include "app/ToolConfig.h"
#include "calib/eval/ConfigComparisonReport.h"
#include "calib/eval/ConfigComparisonRun.h"
#include "calib/session/SessionReader.h"

#include <filesystem>
#include <iostream>

namespace omnitune {

namespace {

int fail(const std::string& why)
{
    std::cerr << "omnitune-eval: " << why << "\n";
    return 1;
}

}  // namespace

CompareArguments::CompareArguments(int argc, const char* const* argv)
{
    for (int i = 0; i < argc; ++i) {
        args_.emplace_back(argv[i]);
        // "--compare A B": B is not an option of its own, so it is the second config.
        if (args_.back() == "--compare" && i + 2 < argc && std::string(argv[i + 2]).rfind("--", 0) != 0) {
            args_.emplace_back(argv[++i]);
            args_.emplace_back("--compare");
        }
    }
    for (const std::string& a : args_) pointers_.push_back(a.c_str());
}

int runEvalCompare(const CommandLine& cl, const EvaluationOptions& options)
{
    const std::vector<std::string>& files = cl.all("compare");
    if (files.size() != 2) return fail("--compare needs two config files: --compare A.yml B.yml (see --help)");
    if (cl.all("session").size() != 1) return fail("--compare runs over one --session (see --help)");
    if (cl.has("config")) return fail("--compare names both configs; drop --config");
    if (cl.value("format").value_or("md") != "md") return fail("--compare prints Markdown only; drop --format");
    const std::string dir = cl.all("session").front();
    SessionOpen opened = SessionReader::open(dir);
    if (!opened.ok()) return fail(opened.error->toString());
    for (const auto& w : opened.reader->warnings()) std::cerr << "warning: " << w.toString() << "\n";

    ConfigComparisonRequest request;
    request.sourcePath = dir;
    request.truth = opened.reader->truth();
    request.evaluation = options;
    request.savedConfigPath = files[1];
    const std::optional<std::string> algorithm = cl.value("algorithm");
    std::string error;
    const auto a = loadToolConfig(files[0], dir, algorithm, error);
    if (!a) return fail(error);
    const auto b = loadToolConfig(files[1], dir, algorithm, error);
    if (!b) return fail(error);
    request.current = *a;
    request.savedConfig = *b;

    ConfigComparisonResult result;
    StderrProgress progress("omnitune-eval --compare " + std::filesystem::path(dir).filename().string());
    runConfigComparison(request, result, &progress);
    if (!result.ok()) return fail(result.error);
    if (!result.hasSaved) return fail(result.savedNote);
    // The same file twice still gets two rows: name them apart.
    std::string nameA = std::filesystem::path(files[0]).filename().string();
    std::string nameB = std::filesystem::path(files[1]).filename().string();
    if (nameA == nameB) {
        nameA = "A: " + files[0];
        nameB = "B: " + files[1];
    }
    std::cout << configComparisonMarkdown(result, nameA, nameB);
    return 0;
}

}  // namespace omnitune
