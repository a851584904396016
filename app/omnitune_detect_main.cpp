// omnitune-detect: the detector without a GUI, as the robot runs it. One CSV row per frame.
#include "calib/eval/BatchRun.h"
#include "app/CommandLine.h"
#include "calib/eval/DetectionCsv.h"
#include "calib/source/FrameSourceFactory.h"
#include "app/StderrProgress.h"
#include "app/ToolConfig.h"

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

using namespace omnitune;

namespace {

const std::vector<OptionSpec> kOptions = {
    {"config", true, false, "FILE  detector config (default: the session's config.yml)"},
    {"input", true, false, "PATH  session folder, video file, image folder or glob ('dir/*.png')"},
    {"algorithm", true, false, "A     specific | opencv | combined (default: the config's)"},
    {"out", true, false, "FILE  write the CSV here (default: standard output)"},
    {"save-stages", true, false, "DIR   also write the five stage images of every frame as PNG"},
    {"help", false, false, "      this text"},
};

int fail(const std::string& why)
{
    std::cerr << "omnitune-detect: " << why << "\n";
    return 1;
}

void saveStages(const std::string& dir, int index, const StageImages& s)
{
    char name[32];
    std::snprintf(name, sizeof name, "%06d_", index);
    const std::pair<const char*, const cv::Mat*> stages[] = {{"acquired", &s.acquired}, {"segmented", &s.segmented},
                                                             {"grayscale", &s.grayscale}, {"edges", &s.edges},
                                                             {"hough", &s.hough}};
    for (const auto& [stage, img] : stages)
        if (!img->empty()) cv::imwrite((std::filesystem::path(dir) / (name + std::string(stage) + ".png")).string(), *img);
}

}  // namespace

int main(int argc, char** argv)
{
    quietOpenCvLogs();
    const CommandLine cl = parseCommandLine(argc, argv, kOptions);
    if (cl.has("help")) {
        std::cout << usageText("omnitune-detect", "Runs the ball detector over every frame of an input.", kOptions);
        return 0;
    }
    if (!cl.error.empty()) return fail(cl.error + " (see --help)");
    if (!cl.has("input")) return fail("--input is required (see --help)");
    const std::string input = *cl.value("input");

    // The input first: a path that does not exist is the fault to report, not its missing config.
    auto opened = openFrameSource(input);
    if (!opened.ok()) return fail(opened.error);
    for (const auto& w : opened.warnings) std::cerr << "warning: " << w << "\n";
    std::string error;
    const auto config = loadToolConfig(cl.value("config"), input, cl.value("algorithm"), error);
    if (!config) return fail(error);

    std::ofstream file;
    if (auto out = cl.value("out")) {
        file.open(*out);
        if (!file) return fail("cannot write " + *out);
    }
    std::ostream& csv = file.is_open() ? static_cast<std::ostream&>(file) : std::cout;
    const auto stagesDir = cl.value("save-stages");
    if (stagesDir) {
        std::error_code ec;
        std::filesystem::create_directories(*stagesDir, ec);
        if (ec) return fail("cannot create " + *stagesDir + ": " + ec.message());
    }

    try {
        Pipeline pipeline(*config);
        StderrProgress progress("omnitune-detect " + input);
        csv << detectionCsvHeader() << "\n";
        const BatchSummary summary = runBatch(
            *opened.source, pipeline,
            [&](int index, const Frame*, const PipelineResult& r) {
                csv << detectionCsvRow(index, r) << "\n";
                if (!r.ok()) std::cerr << "frame " << index << " skipped: " << r.error << "\n";
                if (stagesDir && r.ok()) saveStages(*stagesDir, index, r.stages);
            },
            &progress, stagesDir.has_value());
        if (!csv) return fail("writing the CSV failed");
        if (summary.processed == 0) return fail("no frame of " + input + " could be processed");
        if (summary.failed > 0) std::cerr << summary.failed << " of " << summary.frames << " frames skipped\n";
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}
