// omnitune-sim: renders a robot tour around a static ball (thesis Fig. 5.1) as a session
// folder with truth.csv and the config it was rendered with.
#include "CommandLine.h"
#include "ConfigParser.h"
#include "SceneSimulator.h"
#include "SessionWriter.h"
#include "StderrProgress.h"
#include "Tour.h"

#include <iostream>

using namespace omnitune;

namespace {

const std::vector<OptionSpec> kOptions = {
    {"out", true, false, "DIR   session folder to write"},
    {"ball", true, false, "KIND  orange | black | white-black-green | blue | white-red | 1..5 (default orange)"},
    {"frames", true, false, "N     frames along the tour (default 300)"},
    {"seed", true, false, "S     noise and distractor seed (default 1)"},
    {"config", true, false, "FILE  camera geometry, distance map and ball model (default: built-in defaults)"},
    {"tour", false, false, "      drive the thesis' five-waypoint tour (the default and only mode)"},
    {"ball-x", true, false, "M     ball position on the field, m (default -1; the thesis spot -0.05, 2 is on a line)"},
    {"ball-y", true, false, "M     (default 3)"},
    {"no-ball", false, false, "      leave the ball out (a session for false positives)"},
    {"shadow", false, false, "      the robot head's round shadow on the carpet in every frame"},
    {"feet", false, false, "      a person standing beside the tour in every frame"},
    {"no-obstacles", false, false, "      no other robots on the field"},
    {"light", true, false, "F     light level factor (default 1)"},
    {"gradient", true, false, "F     light gradient / vignetting, 0..1 (default 0)"},
    {"noise", true, false, "F     sensor noise sigma, grey levels (default 2)"},
    {"compression", true, false, "N     PNG zlib level 0..9 (default 1: fast; 9: smallest, for bundled sessions)"},
    {"overwrite", false, false, "      replace an existing session in --out"},
    {"help", false, false, "      this text"},
};

int fail(const std::string& why)
{
    std::cerr << "omnitune-sim: " << why << "\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv)
{
    const CommandLine cl = parseCommandLine(argc, argv, kOptions);
    if (cl.has("help")) {
        std::cout << usageText("omnitune-sim", "Renders a simulated session with ground truth.", kOptions);
        return 0;
    }
    if (!cl.error.empty()) return fail(cl.error + " (see --help)");
    if (!cl.has("out")) return fail("--out is required (see --help)");

    TourOptions tour;
    if (auto b = cl.value("ball")) {
        const auto kind = parseBallKind(*b);
        if (!kind) return fail("unknown --ball '" + *b + "' (see --help)");
        tour.ball = *kind;
    }
    // Numeric options: each names itself when it is not a number.
    auto number = [&](const char* name, double& target) {
        if (auto v = cl.value(name)) {
            const auto d = parseDouble(*v);
            if (!d) throw std::invalid_argument(std::string("--") + name + " needs a number, not '" + *v + "'");
            target = *d;
        }
    };
    double frames = tour.frames;
    double seed = tour.seed;
    try {
        number("frames", frames);
        number("seed", seed);
        number("ball-x", tour.ballX);
        number("ball-y", tour.ballY);
        number("light", tour.lightLevel);
        number("gradient", tour.lightGradient);
        number("noise", tour.noiseSigma);
    } catch (const std::invalid_argument& e) {
        return fail(e.what());
    }
    if (frames < 1 || frames > 100000) return fail("--frames must be 1..100000");
    if (seed < 0) return fail("--seed must not be negative");
    tour.frames = int(frames);
    tour.seed = unsigned(seed);
    tour.shadow = cl.has("shadow");
    tour.feet = cl.has("feet");
    tour.obstacles = !cl.has("no-obstacles");

    Config config;
    if (auto path = cl.value("config")) {
        const ConfigLoad load = loadConfig(*path);
        for (const auto& w : load.warnings) std::cerr << "warning: " << w.toString() << "\n";
        if (!load.ok()) return fail(load.error->toString());
        config = load.config;
    }

    try {
        const SceneSimulator sim(config);
        std::vector<SceneOptions> scenes = makeTour(tour);
        SessionInfo info;
        info.camera = config.camera;
        info.camera.model = "omnitune-sim";
        info.width = config.geometry.imageWidth;
        info.height = config.geometry.imageHeight;
        info.frameRate = config.camera.frameRate;
        info.notes = "omnitune-sim: ball " + std::string(ballKindName(tour.ball)) + (cl.has("no-ball") ? " (left out)" : "") +
                     ", " + std::to_string(tour.frames) + " frames, seed " + std::to_string(tour.seed) +
                     (tour.shadow ? ", head shadow" : "") + (tour.feet ? ", feet" : "") +
                     (tour.obstacles ? "" : ", no obstacles");
        SessionWriterOptions writerOptions;
        writerOptions.overwrite = cl.has("overwrite");
        if (auto level = cl.value("compression")) {
            const auto v = parseInt(*level);
            if (!v || *v < 0 || *v > 9) return fail("--compression must be 0..9, not '" + *level + "'");
            writerOptions.pngCompression = *v;
        }
        SessionCreate created = SessionWriter::create(*cl.value("out"), info, writerOptions);
        if (!created.writer) return fail(created.error->toString());
        SessionWriter& writer = *created.writer;
        if (auto err = writer.writeConfig(config)) return fail(err->toString());
        StderrProgress progress("omnitune-sim");
        for (std::size_t i = 0; i < scenes.size(); ++i) {
            SceneOptions& scene = scenes[i];
            scene.ballPresent = !cl.has("no-ball");
            GroundTruth truth;
            const cv::Mat image = sim.render(scene, &truth);
            TruthRow row;
            row.ballVisible = truth.ballVisible;
            if (truth.ballVisible) {
                row.px = truth.px;
                row.py = truth.py;
                row.radiusPx = truth.radiusPx;
                row.xM = truth.xM;
                row.yM = truth.yM;
            }
            row.robot = truth.pose;
            if (auto err = writer.appendFrame(image, row)) return fail(err->toString());
            progress.update(100.0 * double(i + 1) / double(scenes.size()));
        }
        if (auto err = writer.finish()) return fail(err->toString());
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}
