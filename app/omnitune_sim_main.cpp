// omnitune-sim: renders a robot tour around a static ball (thesis Fig. 5.1) as a session
// folder with truth.csv and the config it was rendered with; or, with --optics, frames ray cast
// through a physical catadioptric camera (calib/sim/optics/) with the config fitted from what a
// team would measure on it.
#include "app/CommandLine.h"
#include "app/ToolConfig.h"
#include "app/StderrProgress.h"
#include "calib/session/Session.h"
#include "calib/sim/TourRecording.h"
#include "calib/sim/optics/OpticsRecording.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

using namespace omnitune;

namespace {

const std::vector<OptionSpec> kOptions = {
    {"out", true, false, "DIR   session folder to write"},
    {"ball", true, false, "KIND  orange | black | white-black-green | blue | white-red | green-white |\n"
                          "                          yellow-white | 1..5 (default orange)"},
    {"frames", true, false, "N     frames along the tour (default 300; --optics: 30)"},
    {"seed", true, false, "S     noise and distractor seed (default 1)"},
    {"config", true, false, "FILE  camera geometry, distance map and ball model (default: built-in defaults)"},
    {"tour", false, false, "      drive the thesis' five-waypoint tour (the default and only mode)"},
    {"ball-x", true, false, "M     ball position on the field, m (default -1; the thesis spot -0.05, 2 is on a line)"},
    {"ball-y", true, false, "M     (default 3)"},
    {"no-ball", false, false, "      leave the ball out (a session for false positives)"},
    {"shadow", false, false, "      the robot head's round shadow on the carpet in every frame"},
    {"feet", false, false, "      a person standing beside the tour in every frame"},
    {"no-obstacles", false, false, "      no other robots on the field"},
    {"light", true, false, "F     light level factor (default 1); with --optics: dim | normal | bright | uneven"},
    {"gradient", true, false, "F     light gradient / vignetting, 0..1 (default 0)"},
    {"noise", true, false, "F     sensor noise sigma, grey levels (default 2)"},
    {"motion-blur", true, false, "PX    blur the ball along its image direction by this length (default 0)"},
    {"occlusion", true, false, "F     share of the ball hidden behind a robot edge, 0..0.9 (default 0)"},
    {"compression", true, false, "N     PNG zlib level 0..9 (default 1: fast; 9: smallest, for bundled sessions)"},
    {"overwrite", false, false, "      replace an existing session in --out"},
    {"optics", false, false, "      ray cast through a catadioptric camera instead of the tour (docs/simulator.md);\n"
                             "                          config.yml is fitted from measurements/, never the truth"},
    {"distractors", true, false, "D     --optics: none | robots | noise | rods (default none)"},
    {"carpet", true, false, "C     --optics: green | cyan-green | dark-green | teal (default green)"},
    {"mirror", true, false, "M     --optics: hyperbolic | spherical (default hyperbolic)"},
    {"size", true, false, "WxH   --optics: 640x480 | 480x480 (default 640x480)"},
    {"help", false, false, "      this text"},
};

int fail(const std::string& why)
{
    std::cerr << "omnitune-sim: " << why << "\n";
    return 1;
}

std::string formatRange(double min, double max)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g..%g", min, max);
    return buf;
}

// A name from `names` (index = enum value) or a message.
template <typename Enum>
bool pickName(const CommandLine& cl, const char* option, const std::vector<std::string>& names, Enum& target,
              std::string& error)
{
    const auto v = cl.value(option);
    if (!v) return true;
    for (std::size_t i = 0; i < names.size(); ++i)
        if (*v == names[i]) {
            target = Enum(i);
            return true;
        }
    std::string all;
    for (const auto& n : names) all += (all.empty() ? "" : " | ") + n;
    error = "unknown --" + std::string(option) + " '" + *v + "' (" + all + ")";
    return false;
}

int runOptics(const CommandLine& cl)
{
    OpticsCell cell;
    cell.frames = 30;
    std::string error;
    if (auto b = cl.value("ball")) {
        const auto kind = parseBallKind(*b);
        if (!kind) return fail("unknown --ball '" + *b + "' (see --help)");
        cell.ball = *kind;
    }
    if (!pickName(cl, "light", {"dim", "normal", "bright", "uneven"}, cell.light, error) ||
        !pickName(cl, "distractors", {"none", "robots", "noise", "rods"}, cell.distractors, error) ||
        !pickName(cl, "carpet", {"green", "cyan-green", "dark-green", "teal"}, cell.carpet, error) ||
        !pickName(cl, "mirror", {"hyperbolic", "spherical"}, cell.mirror, error))
        return fail(error);
    if (auto v = cl.value("size")) {
        if (*v == "640x480") cell.image = {640, 480};
        else if (*v == "480x480") cell.image = {480, 480};
        else return fail("unknown --size '" + *v + "' (640x480 | 480x480)");
    }
    if (auto v = cl.value("frames")) {
        const auto i = parseInt(*v);
        if (!i || *i < 1 || *i > 100000) return fail("--frames must be a whole number in 1..100000, not '" + *v + "'");
        cell.frames = *i;
    }
    if (auto v = cl.value("seed")) {
        const auto i = parseInt(*v);
        if (!i || *i < 0) return fail("--seed must be a whole number in 0..2147483647, not '" + *v + "'");
        cell.seed = unsigned(*i);
    }
    for (const char* tourOnly : {"tour", "ball-x", "ball-y", "shadow", "feet", "no-obstacles", "gradient", "noise",
                                 "motion-blur", "occlusion"})
        if (cl.has(tourOnly)) return fail(std::string("--") + tourOnly + " is for the tour, not --optics (see --help)");
    cell.ballPresent = !cl.has("no-ball");
    Config base;
    if (cl.has("config")) {
        const auto loaded = loadToolConfig(cl.value("config"), {}, std::nullopt, error);
        if (!loaded) return fail(error);
        base = *loaded;
    }
    SessionWriterOptions writer;
    writer.overwrite = cl.has("overwrite");
    if (auto v = cl.value("compression")) {
        const auto i = parseInt(*v);
        if (!i || *i < 0 || *i > 9) return fail("--compression must be a whole number in 0..9, not '" + *v + "'");
        writer.pngCompression = *i;
    }
    const std::string out = *cl.value("out");
    if (!cl.has("overwrite") && std::filesystem::exists(std::filesystem::path(out) / kSessionInfoFile))
        return fail(out + " already holds a session: choose another folder or pass --overwrite");
    try {
        StderrProgress progress("omnitune-sim");
        const OpticsRecordingResult result = recordOpticsSession(out, cell, base, writer, &progress);
        if (!result.ok()) return fail(*result.error);
        std::cerr << "omnitune-sim: " << opticsCellName(cell) << ": " << result.frames << " frames, "
                  << result.visibleBalls << " with the ball visible\n";
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
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
    if (cl.has("optics")) return runOptics(cl);
    for (const char* opticsOnly : {"distractors", "carpet", "mirror", "size"})
        if (cl.has(opticsOnly)) return fail(std::string("--") + opticsOnly + " needs --optics");

    TourRecordingOptions recording;
    TourOptions& tour = recording.tour;
    if (auto b = cl.value("ball")) {
        const auto kind = parseBallKind(*b);
        if (!kind) return fail("unknown --ball '" + *b + "' (see --help)");
        tour.ball = *kind;
    }
    // Numeric options: each is checked against its range and names itself when it is off.
    auto number = [&](const char* name, double min, double max, double& target) {
        if (auto v = cl.value(name)) {
            const auto d = parseDouble(*v);
            if (!d || !std::isfinite(*d) || *d < min || *d > max)
                throw std::invalid_argument(std::string("--") + name + " must be a number in " + formatRange(min, max) +
                                            ", not '" + *v + "'");
            target = *d;
        }
    };
    auto integer = [&](const char* name, int min, int max, int& target) {
        if (auto v = cl.value(name)) {
            const auto i = parseInt(*v);
            if (!i || *i < min || *i > max)
                throw std::invalid_argument(std::string("--") + name + " must be a whole number in " +
                                            std::to_string(min) + ".." + std::to_string(max) + ", not '" + *v + "'");
            target = *i;
        }
    };
    int seed = int(tour.seed);
    try {
        integer("frames", 1, 100000, tour.frames);
        integer("seed", 0, 2147483647, seed);
        number("ball-x", -20, 20, tour.ballX);
        number("ball-y", -20, 20, tour.ballY);
        number("light", 0.05, 5, tour.lightLevel);
        number("gradient", 0, 1, tour.lightGradient);
        number("noise", 0, 100, tour.noiseSigma);
        number("motion-blur", 0, 50, recording.motionBlurPx);
        number("occlusion", 0, 0.9, recording.occlusion);
        integer("compression", 0, 9, recording.writer.pngCompression);
    } catch (const std::invalid_argument& e) {
        return fail(e.what());
    }
    Config config;
    if (cl.has("config")) {
        std::string error;
        const auto loaded = loadToolConfig(cl.value("config"), {}, std::nullopt, error);
        if (!loaded) return fail(error);
        config = *loaded;
    }

    recording.tour.seed = unsigned(seed);
    recording.tour.shadow = cl.has("shadow");
    recording.tour.feet = cl.has("feet");
    recording.tour.obstacles = !cl.has("no-obstacles");
    recording.ballPresent = !cl.has("no-ball");
    recording.writer.overwrite = cl.has("overwrite");
    const std::string out = *cl.value("out");
    if (!cl.has("overwrite") && std::filesystem::exists(std::filesystem::path(out) / kSessionInfoFile))
        return fail(out + " already holds a session: choose another folder or pass --overwrite");
    try {
        StderrProgress progress("omnitune-sim");
        const TourRecordingResult result = recordTour(out, config, recording, &progress);
        if (!result.ok()) return fail(result.error->toString());
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}
