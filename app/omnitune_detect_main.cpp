// omnitune-detect: the detector without a GUI, as the robot runs it. One CSV row per frame.
#include "calib/eval/BatchRun.h"
#include "app/CommandLine.h"
#include "calib/eval/DetectionCsv.h"
#include "calib/source/FrameSourceFactory.h"
#include "app/StderrProgress.h"
#include "app/ToolConfig.h"

#include "calib/eval/OutputFile.h"

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
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

// Stops the batch once `error` is set, and otherwise passes progress and Ctrl+C through.
class CancelOnError : public Progress {
public:
    CancelOnError(Progress& inner, const std::optional<std::string>& error) : inner_(inner), error_(error) {}
    void update(double percent) override { inner_.update(percent); }
    bool isCancelRequested() const override { return error_.has_value() || inner_.isCancelRequested(); }

private:
    Progress& inner_;
    const std::optional<std::string>& error_;
};

int fail(const std::string& why)
{
    std::cerr << "omnitune-detect: " << why << "\n";
    return 1;
}

// Each stage image as NNNNNN_stage.png; the first file that cannot be written is the fault.
std::optional<std::string> saveStages(const std::string& dir, int index, const StageImages& s)
{
    char name[32];
    std::snprintf(name, sizeof name, "%06d_", index);
    const std::pair<const char*, const cv::Mat*> stages[] = {{"acquired", &s.acquired}, {"segmented", &s.segmented},
                                                             {"grayscale", &s.grayscale}, {"edges", &s.edges},
                                                             {"hough", &s.hough}};
    for (const auto& [stage, img] : stages) {
        if (img->empty()) continue;
        const std::string path = (std::filesystem::path(dir) / (name + std::string(stage) + ".png")).string();
        std::vector<std::uint8_t> png;
        if (!cv::imencode(".png", *img, png)) return path + ": cannot encode the " + stage + " stage as PNG";
        std::string error;
        auto file = OutputFile::open(path, false, error);
        if (!file) return error;
        if (auto err = file->write({reinterpret_cast<const char*>(png.data()), png.size()})) return err;
        if (auto err = file->commit()) return err;
    }
    return std::nullopt;
}

// The fault when `out` is a file the run reads: the config, its mask or the input's own files.
std::optional<std::string> writesOntoInput(const std::string& out, const FrameSource& source,
                                           const std::string& configPath, const Config& config)
{
    std::vector<std::string> inputs = {configPath};
    if (!config.geometry.maskFile.empty())
        inputs.push_back((std::filesystem::path(configPath).parent_path() / config.geometry.maskFile).string());
    for (const std::string& in : inputs)
        if (sameFile(out, in)) return "--out " + out + " is " + in + ", an input of this run; refusing to overwrite it";
    if (source.readsFile(out))
        return "--out " + out + " is a file of the input " + source.description() + "; refusing to overwrite it";
    return std::nullopt;
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

    std::string configPath;
    const auto config = loadToolConfig(cl.value("config"), input, cl.value("algorithm"), error, &configPath);
    if (!config) return fail(error);

    // Nothing is created before every check passed, and the CSV goes through a temporary file
    // renamed at the end: a failed run leaves a previous --out file as it was.
    std::optional<OutputFile> file;
    if (auto out = cl.value("out")) {
        if (auto why = writesOntoInput(*out, *opened.source, configPath, *config)) return fail(*why);
        auto target = OutputFile::open(*out, true, error);
        if (!target) return fail(error);
        file.emplace(std::move(*target));
    } else {
        file.emplace(OutputFile::standardOutput());
    }
    const auto stagesDir = cl.value("save-stages");
    if (stagesDir) {
        std::error_code ec;
        std::filesystem::create_directories(*stagesDir, ec);
        if (ec) return fail("cannot create " + *stagesDir + ": " + ec.message());
    }

    try {
        Pipeline pipeline(*config);
        StderrProgress progress("omnitune-detect " + input);
        // The first failed write stops the run: going on would only fill the log.
        std::optional<std::string> writeError = file->write(detectionCsvHeader() + "\n");
        CancelOnError stop(progress, writeError);
        const BatchSummary summary = runBatch(
            *opened.source, pipeline,
            [&](int index, const Frame*, const PipelineResult& r) {
                if (writeError) return;
                writeError = file->write(detectionCsvRow(index, r) + "\n");
                if (!r.ok()) std::cerr << "frame " << index << " skipped: " << r.error << "\n";
                if (stagesDir && r.ok() && !writeError) writeError = saveStages(*stagesDir, index, r.stages);
            },
            &stop, stagesDir.has_value());
        if (!writeError) writeError = file->commit();
        if (writeError) return fail(*writeError);
        if (summary.processed == 0) return fail("no frame of " + input + " could be processed");
        if (summary.failed > 0) std::cerr << summary.failed << " of " << summary.frames << " frames skipped\n";
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}
