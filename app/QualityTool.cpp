#include "app/QualityTool.h"

#include "app/StderrProgress.h"
#include "calib/eval/FalsePositiveList.h"
#include "calib/eval/MissList.h"
#include "calib/eval/OutputFile.h"
#include "calib/eval/QualityFloors.h"
#include "calib/eval/QualityReport.h"
#include "calib/fit/NumberCsv.h"
#include "core/ConfigParser.h"
#include "core/Stopwatch.h"

#include <cstdio>
#include <iostream>

namespace omnitune {

std::vector<OptionSpec> qualityToolOptions()
{
    return {
        {"quality-matrix", false, false, "      the quality gate's matrix on the optics simulator (no --session)"},
        {"frames", true, false, "N     with --quality-matrix: frames per ball cell (default: the floors file's, else 1)"},
        {"ball-free-frames", true, false, "N     with --quality-matrix: frames per ball-free cell (default 2)"},
        {"seed", true, false, "N     with --quality-matrix: the matrix seed (default 1)"},
        {"spread-directions", false, false, "      with --quality-matrix: ball directions in golden-angle steps per frame (the matrix before 2026-12-02) instead of drawn per frame"},
        {"floors", true, false, "FILE  with --quality-matrix: check these floors as the gate test does"},
        {"write-floors", true, false, "FILE  with --quality-matrix: write floors (measured less a margin) to FILE"},
        {"threads", true, false, "N     with --quality-matrix: cells on N threads (default 1, honest timings; 0: all)"},
        {"misses", false, false, "      with --quality-matrix: why balls were missed and what false positives hit, per condition"},
        {"cells", true, false, "A,B   with --quality-matrix: only the cells whose name holds every one of these parts (e.g. dim,rods)"},
        {"pixel-format", true, false, "F     with --quality-matrix: the format the detector reads the frames in: bgr8 or uyvy (YUV 4:2:2, an IIDC camera's); default: the floors file's, else bgr8"},
        {"auto-colours", true, false, "N     with --quality-matrix: each cell's colours by Auto colours from N frames of its field and light (default 0: the default colours)"},
        {"false-positives", false, false, "      with --quality-matrix: list every false-positive frame with its scores"},
        {"fp-crops", true, false, "DIR   with --false-positives: also write each one's surroundings, enlarged, as PNGs to DIR"},
        {"miss-list", false, false, "      with --quality-matrix: list every missed ball frame of combined (the candidate at the ball, its scores; \"(prefilter)\": refused before validation)"},
        {"miss-cause", true, false, "NAME  with --miss-list: only misses of this cause (e.g. non-green, no-candidate, circularity)"},
        {"miss-crops", true, false, "DIR   with --miss-list: also write each missed ball's surroundings, enlarged, as PNGs to DIR"},
        {"deviations", true, false, "FILE  with --quality-matrix: also run each deviation from the thesis switched off (specific, combined)"},
    };
}

namespace {

int fail(const std::string& why)
{
    std::cerr << "omnitune-eval: " << why << "\n";
    return 1;
}

bool positive(const CommandLine& cl, const std::string& name, int& out, std::string& error)
{
    const auto text = cl.value(name);
    if (!text) return true;
    const auto v = parseInt(*text);
    if (!v || *v < 1 || *v > 10000) {
        error = "--" + name + " must be a whole number from 1 to 10000, not '" + *text + "'";
        return false;
    }
    out = *v;
    return true;
}

}  // namespace

int runQualityTool(const CommandLine& cl)
{
    QualityMatrixOptions matrix;
    std::optional<QualityFloorsFile> floors;
    if (auto path = cl.value("floors")) {
        const auto text = readTextFile(*path);
        if (!text) return fail(*path + ": cannot be read");
        std::string error;
        floors = parseQualityFloors(*text, error);
        if (!floors) return fail(*path + ": " + error);
        matrix = floors->matrix;  // measure what the floors were measured on
    }
    std::string error;
    int seed = int(matrix.seed);
    if (!positive(cl, "frames", matrix.framesPerCell, error) ||
        !positive(cl, "ball-free-frames", matrix.ballFreeFramesPerCell, error) || !positive(cl, "seed", seed, error))
        return fail(error);
    matrix.seed = unsigned(seed);
    if (cl.has("spread-directions")) matrix.directions = OpticsDirections::Spread;

    Config base;
    if (auto path = cl.value("config")) {
        const ConfigLoad load = loadConfig(*path);
        if (!load.ok()) return fail(load.error->toString());
        base = load.config;
    }
    std::vector<QualityVariant> variants = algorithmVariants();
    if (auto path = cl.value("deviations")) {
        const auto text = readTextFile(*path);
        if (!text) return fail(*path + ": cannot be read");
        const std::vector<ConfigOverride> deviations = parseDeviationsCsv(*text, error);
        if (!error.empty()) return fail(*path + ": " + error);
        // Specific and combined (which includes the OpenCV path): the two the targets hold first.
        for (QualityVariant& v : deviationVariants(deviations, {Algorithm::Specific, Algorithm::Combined}))
            variants.push_back(std::move(v));
    }

    QualityRunOptions runOptions;
    if (auto t = cl.value("threads")) {
        const auto v = parseInt(*t);
        if (!v || *v < 0 || *v > 256) return fail("--threads must be a whole number from 0 to 256, not '" + *t + "'");
        runOptions.threads = *v;
    }
    if (auto t = cl.value("auto-colours")) {
        const auto v = parseInt(*t);
        if (!v || *v < 0 || *v > 30) return fail("--auto-colours must be a whole number from 0 to 30, not '" + *t + "'");
        runOptions.autoColourFrames = *v;
    }
    if (floors) runOptions.pixelFormat = floors->pixelFormat;  // the format the floors were measured on
    if (auto f = cl.value("pixel-format")) {
        PixelFormat asked = PixelFormat::Bgr8;
        if (*f == "uyvy") asked = PixelFormat::Uyvy;
        else if (*f != "bgr8") return fail("--pixel-format must be bgr8 or uyvy, not '" + *f + "'");
        if (floors && asked != floors->pixelFormat)
            return fail("--pixel-format " + *f + ": the floors in " + *cl.value("floors") + " were measured on " +
                        std::string(pixelFormatName(floors->pixelFormat)) + " frames (drop --pixel-format)");
        runOptions.pixelFormat = asked;
    }
    std::optional<MissCause> missCause;
    if (auto name = cl.value("miss-cause")) {
        missCause = missCauseNamed(*name);
        if (!missCause) return fail("--miss-cause '" + *name + "' is not a cause of a miss (see the --misses table's columns)");
    }
    runOptions.recordMisses = cl.has("miss-list");
    runOptions.explainRejections = cl.has("misses");
    std::vector<OpticsCell> cells = qualityMatrixCells(matrix);
    if (auto parts = cl.value("cells")) {
        cells = filterOpticsCells(cells, *parts);
        if (cells.empty()) return fail("--cells '" + *parts + "' matches no cell of the matrix");
    }
    QualityRun run;
    Stopwatch clock;
    try {
        StderrProgress progress("omnitune-eval quality matrix");
        run = runQuality(cells, variants, base, runOptions, &progress);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    const double totalS = clock.total() / 1000.0;

    int ballCells = 0;
    for (const OpticsCell& c : cells) ballCells += c.ballPresent;
    char head[512];
    std::snprintf(head, sizeof head,
                  "%zu cells: %d with a ball x %d frames, %d ball-free x %d frames; seed %u%s; %zu detector runs per frame. "
                  "Rendering and calibration %.1f s (over threads), wall %.1f s.\n\n",
                  cells.size(), ballCells, matrix.framesPerCell, int(cells.size()) - ballCells,
                  matrix.ballFreeFramesPerCell, matrix.seed, runOptions.pixelFormat == PixelFormat::Uyvy ? "; frames read as UYVY" : "", variants.size(), run.renderMs / 1000.0, totalS);
    const std::vector<std::size_t> shipped = shippedVariants(run);
    std::string md = head;
    md += "### Overall\n\n" + qualitySummaryMarkdown(run, shipped) + "\n";
    md += "### By condition (balls found)\n\n" + qualityBreakdownMarkdown(run, shipped) + "\n";
    md += "### The 12 worst cells (combined)\n\n" + qualityWorstCellsMarkdown(run, shipped.back(), 12) + "\n";
    if (cl.has("misses")) {
        md += "### Why balls were missed (combined; cause of each missed frame)\n\n" +
              qualityMissesMarkdown(run, shipped.back()) + "\n";
        md += "### Why balls were missed (specific)\n\n" + qualityMissesMarkdown(run, shipped.front()) + "\n";
        // The OpenCV algorithm alone (issue 9 section 4: its own floor), when it ran.
        for (std::size_t v : shipped)
            if (run.variants[v].algorithm == Algorithm::OpenCv)
                md += "### Why balls were missed (OpenCV)\n\n" + qualityMissesMarkdown(run, v) + "\n";
        md += "### What the false positives hit\n\n" + qualityFalsePositivesMarkdown(run, shipped) + "\n";
    }
    if (cl.has("false-positives")) {
        md += "### Each false positive\n\n" + falsePositiveListMarkdown(run, shipped) + "\n";
        if (auto dir = cl.value("fp-crops"))
            if (auto e = writeFalsePositiveCrops(run, shipped, *dir)) return fail(*e);
    }
    if (cl.has("miss-list")) {
        md += "### Each missed ball (combined)\n\n" + missListMarkdown(run, {shipped.back()}, missCause) + "\n";
        if (auto dir = cl.value("miss-crops"))
            if (auto e = writeMissCrops(run, {shipped.back()}, *dir, missCause)) return fail(*e);
    }
    if (run.variants.size() > shipped.size())
        md += "### Each deviation from the thesis switched off (the thesis' value)\n\n" + qualityDeviationsMarkdown(run) + "\n";
    bool fell = false;
    if (floors) {
        md += "### Against the floors\n\n```\n";
        for (const QualityFloorCheck& c : checkQualityFloors(run, *floors)) {
            md += c.line + "\n";
            fell = fell || !c.passed;
        }
        md += "```\n";
    }
    OutputFile out = OutputFile::standardOutput();
    if (auto e = out.write(md)) return fail(*e);
    if (auto e = out.commit()) return fail(*e);

    if (auto path = cl.value("write-floors")) {
        auto file = OutputFile::open(*path, true, error);
        if (!file) return fail(error);
        if (auto e = file->write(serializeQualityFloors(floorsFromRun(run, matrix, runOptions.pixelFormat)))) return fail(*e);
        if (auto e = file->commit()) return fail(*e);
        std::cerr << "omnitune-eval: floors written to " << *path << "\n";
    }
    return fell ? 1 : 0;
}

}  // namespace omnitune
