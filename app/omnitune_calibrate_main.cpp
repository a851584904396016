// omnitune-calibrate: the window's geometry fits on the command line (calib/fit/). Each
// subcommand reads a config, fits one part of it, prints what it fitted with its residuals and
// writes the updated config atomically (the previous OUT kept as OUT.bak). When a fit cannot be
// made it exits non-zero with a one-line reason and writes nothing.
#include "app/ColourProfileCommand.h"
#include "app/CommandLine.h"
#include "app/StderrProgress.h"
#include "app/ToolConfig.h"
#include "calib/colour/AutoColour.h"
#include "calib/fit/BallModelFit.h"
#include "calib/fit/BallSamplesCsv.h"
#include "calib/fit/BodyFit.h"
#include "calib/fit/CalibrationPointsCsv.h"
#include "calib/fit/DistanceMapFit.h"
#include "calib/fit/FitFrames.h"
#include "calib/fit/FitText.h"
#include "calib/fit/MirrorFit.h"
#include "calib/fit/RimFit.h"
#include "calib/mask/AutoMask.h"
#include "calib/mask/MaskImport.h"
#include "calib/session/Session.h"
#include "calib/session/SessionReader.h"
#include "calib/source/FrameSourceFactory.h"
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"
#include "core/RegularFile.h"
#include "core/RingCoverage.h"

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <iostream>

using namespace omnitune;

namespace {

const std::vector<OptionSpec> kOptions = {
    {"input", true, false, "PATH  session, video, image folder or glob ('dir/*.png'); rim, colours and ball-model"},
    {"config", true, false, "FILE  the config to start from (default: the session's config.yml; rim and\n"
                            "                          distance-map with radius_px points fall back to the defaults)"},
    {"out", true, false, "FILE  where the updated config goes (an existing file is kept as FILE.bak)"},
    {"frames", true, false, "N     rim, colours and mask: frames used, spread over the input (default 8; mask 16)"},
    {"margin", true, false, "PX    rim: outer radius this far inside the found rim (default 2)"},
    {"no-body", false, false, "      rim: keep the config's inner radius (fit the rim from one frame)"},
    {"points", true, false, "FILE  distance-map: CSV radius_px,distance_m or x,y,distance_m"},
    {"degree", true, false, "N     distance-map: polynomial degree 1..6 (default 3)"},
    {"height", true, false, "M     distance-map: height of the mirror's viewpoint above the floor, for the\n"
                                      "                          ball-height correction (default: keep the config's)"},
    {"samples", true, false, "FILE  ball-model: CSV distance_px,radius_px or distance_m,radius_px instead of\n"
                             "                          the session's truth marks"},
    {"auto", false, false, "      mask: propose the robot's structure from frames in which the robot drives or turns"},
    {"import", true, false, "FILE  mask: convert a mask image made elsewhere (needs --config or a session's)"},
    {"process", true, false, "SIDE  mask --import: white (bright, any colour, = process; the default) or black"},
    {"profile-list", false, false, "      colours: list the venue profiles beside --config (CONFIG_DIR/colour-profiles/)"},
    {"profile-save", true, false, "NAME  colours: save --config's colours as the profile NAME (no --input, no --out)"},
    {"profile-load", true, false, "NAME  colours: write --out with --config's settings and profile NAME's colours"},
    {"help", false, false, "      this text"},
};

const char* const kSummary =
    "Fits the camera geometry and writes it into a config.\n"
    "subcommands:\n"
    "  rim            mirror centre, outer radius (from the rim) and inner radius (from the robot body)\n"
    "  colours        first colour calibration: the dominant hue in the used area is the carpet; green,\n"
    "                 white and black set from it (run after rim: it needs the geometry)\n"
    "  colours --profile-list | --profile-save NAME | --profile-load NAME --out OUT.yml\n"
    "                 the window's venue profiles: colour calibrations by name in colour-profiles/ beside\n"
    "                 --config\n"    "  distance-map   image radius -> ground distance from --points\n"
    "  ball-model     expected ball radius r(d) from the truth marks of the --input session or --samples\n"
    "  mask --auto    robot mask (body, support rods, reflections): what stays put while the field moves\n"
    "  mask --import  a mask made elsewhere, in OmniTune's convention (white = process)";

int fail(const std::string& why)
{
    std::cerr << "omnitune-calibrate: " << why << "\n";
    return 1;
}

std::string sizeText(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

// The config to start from: --config, else the config the input session names (the one rule of
// calib/session/SessionConfig.h that the window and every tool follow), else (where the
// geometry does not matter yet) the defaults.
std::optional<Config> startingConfig(const CommandLine& cl, bool defaultsServe, const std::string& needsWhat,
                                     std::string& error)
{
    const std::string input = cl.value("input").value_or("");
    bool sessionConfig = false;
    if (!input.empty() && std::filesystem::is_directory(input)) {
        const SessionOpen session = SessionReader::open(input);
        // A config_file it refuses goes to loadToolConfig too, which says why.
        sessionConfig = session.ok() && (session.reader->hasConfig() || session.reader->configIssue());
    }
    if (cl.has("config") || sessionConfig) return loadToolConfig(cl.value("config"), input, std::nullopt, error);
    if (!defaultsServe) {
        error = needsWhat + ": give --config IN.yml (run 'omnitune-calibrate rim' first for a new camera)";
        return std::nullopt;
    }
    std::cerr << "note: no --config" << (input.empty() ? "" : " and no config.yml in " + input)
              << ": starting from the defaults\n";
    return Config{};
}

int save(const Config& config, const std::string& out)
{
    const bool existed = std::filesystem::exists(out);
    if (const auto err = saveConfig(config, out, true)) return fail(err->toString());
    std::cout << "wrote " << out
              << (existed ? " (" + out + ".bak keeps the file from before OmniTune first saved over it)" : std::string())
              << "\n";
    return 0;
}

// "39.0000 - 0.283330*d + 0.00055556*d^2"
std::string ballCurveText(double c0, double c1, double c2)
{
    const auto term = [](double c, int decimals, const char* power) {
        return std::string(c < 0 ? " - " : " + ") + fixedText(std::abs(c), decimals) + power;
    };
    return fixedText(c0, 4) + term(c1, 6, "*d") + term(c2, 8, "*d^2");
}

std::string pointText(cv::Point2d p) { return "(" + fixedText(p.x, 2) + ", " + fixedText(p.y, 2) + ")"; }

int runRim(const CommandLine& cl, const std::string& out)
{
    if (!cl.has("input")) return fail("rim needs --input (see --help)");
    const std::string input = *cl.value("input");
    int frameCount = 8;
    if (auto f = cl.value("frames")) {
        const auto v = parseInt(*f);
        if (!v || *v < 1) return fail("--frames must be a positive whole number, not '" + *f + "'");
        frameCount = *v;
    }
    RimFitOptions rimOptions;
    if (auto m = cl.value("margin")) {
        const auto v = parseDouble(*m);
        if (!v || *v < 0) return fail("--margin must be a number of pixels >= 0, not '" + *m + "'");
        rimOptions.marginPx = *v;
    }
    auto opened = openFrameSource(input);
    if (!opened.ok()) return fail(opened.error);
    for (const auto& w : opened.warnings) std::cerr << "warning: " << w << "\n";
    std::string error;
    auto config = startingConfig(cl, true, "", error);
    if (!config) return fail(error);

    FitFrames frames = readFitFrames(*opened.source, frameCount);
    for (const auto& w : frames.warnings) std::cerr << "warning: " << w << "\n";
    if (!frames.ok()) return fail(frames.error->toString());
    const cv::Size size = frames.images.front().size();
    StderrProgress progress("omnitune-calibrate rim");
    const MirrorFitResult mirror = fitMirror(frames.images, *config, rimOptions, !cl.has("no-body"), &progress);
    if (!mirror.ok())
        return fail(mirror.error->toString() +
                    (mirror.error->kind == FitErrorKind::TooFewFrames || mirror.error->kind == FitErrorKind::StaticField
                         ? " (or give --no-body to fit only the rim)"
                         : ""));
    for (const auto& line : mirror.adapted) std::cerr << "note: adapted to these frames first: " << line << "\n";
    const std::optional<BodyFit>& body = mirror.body;
    const RimFit& r = mirror.rim;
    const cv::Size oldSize(config->geometry.imageWidth, config->geometry.imageHeight);
    std::cout << "rim: " << frames.images.size() << " frame(s) of " << opened.source->description() << ", "
              << sizeText(size) << (oldSize != size ? " (the config had " + sizeText(oldSize) + ")" : std::string()) << "\n"
              << "  centre        " << pointText(r.centre) << " px (was "
              << pointText({config->geometry.centerX, config->geometry.centerY}) << ")\n"
              << "  mirror rim    " << fixedText(r.rimRadius, 2) << " px: " << r.inliers << " of " << r.points.size()
              << " edge points from " << r.raysCast << " rays kept, residual RMS " << fixedText(r.rmsPx, 2) << " px, "
              << "spread over " << fixedText(r.coverageDeg, 0) << " deg\n"
              << "  outer radius  " << fixedText(r.outerRadius, 2) << " px (rim - " << fixedText(rimOptions.marginPx)
              << " px; was " << fixedText(config->geometry.outerRadius, 2) << ")\n";
    if (body)
        std::cout << "  inner radius  " << fixedText(body->innerRadius, 2) << " px (robot body edge "
                  << fixedText(body->bodyRadius, 2) << " px + " << fixedText(BodyFitOptions{}.marginPx)
                  << " px; ring variance " << fixedText(body->bodyLevel) << " on the body, "
                  << fixedText(body->fieldLevel) << " over the field; was " << fixedText(config->geometry.innerRadius, 2)
                  << ")\n";
    else
        std::cout << "  inner radius  " << fixedText(config->geometry.innerRadius, 2) << " px (kept: --no-body)\n";

    config = mirror.config;
    const auto& sensors = config->sensors;
    // A pixel either way is no fault worth a note; a sensor ray into the housing is.
    if (sensors.innerRadius < config->geometry.innerRadius - 1 || sensors.outerRadius > config->geometry.outerRadius + 1)
        std::cerr << "note: the radial sensors run from " << fixedText(sensors.innerRadius) << " to "
                  << fixedText(sensors.outerRadius) << " px, outside the new ring; set sensors.inner_radius and "
                  << "outer_radius to match\n";
    return save(*config, out);
}

// For fits that judge pixels of the config's geometry (colours, mask --auto): the config and
// --frames frames of --input (spread over it), which must have the geometry's size.
struct GeometryFrames {
    Config config;
    FitFrames frames;
    std::string source;  // the source's description, for the report
};

std::optional<GeometryFrames> framesForGeometry(const CommandLine& cl, int defaultCount, const std::string& needsWhat,
                                                std::string& error)
{
    int frameCount = defaultCount;
    if (auto f = cl.value("frames")) {
        const auto v = parseInt(*f);
        if (!v || *v < 1) {
            error = "--frames must be a positive whole number, not '" + *f + "'";
            return std::nullopt;
        }
        frameCount = *v;
    }
    const std::string input = *cl.value("input");
    auto opened = openFrameSource(input);
    if (!opened.ok()) {
        error = opened.error;
        return std::nullopt;
    }
    for (const auto& w : opened.warnings) std::cerr << "warning: " << w << "\n";
    auto config = startingConfig(cl, false, needsWhat, error);
    if (!config) return std::nullopt;
    GeometryFrames out{*config, readFitFrames(*opened.source, frameCount), opened.source->description()};
    for (const auto& w : out.frames.warnings) std::cerr << "warning: " << w << "\n";
    if (!out.frames.ok()) {
        error = out.frames.error->toString();
        return std::nullopt;
    }
    const cv::Size size = out.frames.images.front().size();
    const cv::Size geometrySize(out.config.geometry.imageWidth, out.config.geometry.imageHeight);
    if (size != geometrySize) {
        error = "the config's geometry is for " + sizeText(geometrySize) + " frames but " + input + " gives " +
                sizeText(size) + " frames: run 'omnitune-calibrate rim' on it first";
        return std::nullopt;
    }
    return out;
}

std::string hsvText(const HsvRange& r)
{
    return "H " + std::to_string(r.hMin) + ".." + std::to_string(r.hMax) + "  S " + std::to_string(r.sMin) + ".." +
           std::to_string(r.sMax) + "  V " + std::to_string(r.vMin) + ".." + std::to_string(r.vMax);
}

int runColours(const CommandLine& cl, const std::string& out)
{
    if (!cl.has("input")) return fail("colours needs --input (see --help)");
    std::string error;
    auto in = framesForGeometry(cl, 8, "colours samples the used area of the config's geometry", error);
    if (!in) return fail(error);
    Config* config = &in->config;
    const FitFrames& frames = in->frames;
    const auto problems = checkConfig(*config);
    if (!problems.empty()) return fail(problems.front().toString());

    const Geometry geometry(config->geometry, config->mask);
    const AutoColourResult r = autoColour(frames.images, geometry, config->colors);
    if (!r.ok()) return fail(*r.error);
    // The classes autoColour sets: the first of each role, before and after.
    const auto boxes = [](const ColorLutOptions& c, ColourRole role) {
        for (const ColourClassDef& k : c.classes) {
            if (k.role != role) continue;
            std::string text = k.name + "  ";
            for (std::size_t i = 0; i < k.boxes.size(); ++i) text += (i ? " | " : "") + hsvText(k.boxes[i]);
            return text;
        }
        return std::string("(no class with role ") + std::string(colourRoleName(role)) + ")";
    };
    std::cout << "colours: " << frames.images.size() << " frame(s) of " << in->source << "\n"
              << "  carpet   hue " << r.carpetHue << ", median S " << r.carpetS << ", median V " << r.carpetV << ", "
              << fixedText(r.carpetPct, 1) << " % of the used area\n"
              << "  field    " << boxes(r.colors, ColourRole::Field) << "  (was " << boxes(config->colors, ColourRole::Field)
              << ")\n"
              << "  line     " << boxes(r.colors, ColourRole::Line) << "  (was " << boxes(config->colors, ColourRole::Line)
              << ")\n"
              << "  black    V <= " << fixedText(r.colors.blackVRatio, 2) << " x the carpet's V per frame (black_relative; "
              << boxes(r.colors, ColourRole::Black) << " when no carpet is seen)\n";
    for (const auto& n : r.notes) std::cout << "  note: " << n << "\n";
    config->colors = r.colors;
    return save(*config, out);
}

int runDistanceMap(const CommandLine& cl, const std::string& out)
{
    if (!cl.has("points")) return fail("distance-map needs --points POINTS.csv (see --help)");
    DistanceMapFitOptions options;
    if (auto d = cl.value("degree")) {
        const auto v = parseInt(*d);
        if (!v || *v < 1 || *v > 6) return fail("--degree must be 1..6, not '" + *d + "'");
        options.degree = *v;
    }
    std::optional<double> height;
    if (auto h = cl.value("height")) {
        height = parseDouble(*h);
        if (!height || *height <= 0) return fail("--height must be a positive number of metres, not '" + *h + "'");
    }
    const CalibrationPointsParse parse = loadCalibrationPoints(*cl.value("points"));
    for (const auto& w : parse.warnings) std::cerr << "warning: " << w.toString() << "\n";
    if (!parse.ok()) return fail(parse.error->toString());
    std::string error;
    auto config = startingConfig(cl, !parse.needsCentre(), *cl.value("points") + " gives image points (x,y): their radius needs the mirror centre", error);
    if (!config) return fail(error);

    const cv::Point2d centre(config->geometry.centerX, config->geometry.centerY);
    const std::vector<DistancePoint> points = toDistancePoints(parse.points, centre);
    const DistanceMapFitResult result = fitDistanceMap(points, options);
    if (!result.ok()) return fail(result.error->toString());
    const DistanceMapFit& f = result.fit;
    std::cout << "distance-map: " << points.size() << " points from " << *cl.value("points") << ", degree "
              << options.degree << ", " << fixedText(f.minRadiusPx) << ".." << fixedText(f.maxRadiusPx) << " px\n"
              << "  residual RMS " << fixedText(f.rmsCm, 2) << " cm, largest " << fixedText(f.maxAbsCm, 2) << " cm\n";
    if (!f.note.empty()) std::cout << "  " << f.note << "\n";  // the points' table, not the asked degree
    for (std::size_t i = 0; i < points.size(); ++i)
        std::cout << "  " << fixedText(points[i].radiusPx, 1) << " px  " << fixedText(points[i].distanceM, 3) << " m  fit "
                  << fixedText(f.distanceAt(points[i].radiusPx), 3) << " m  residual " << fixedText(f.residualsCm[i], 2)
                  << " cm\n";
    std::cout << "  written as a table of " << f.tableRadiiPx.size() << " radii (within "
              << fixedText(f.tableDeviationCm, 2) << " cm of the fit)\n";
    applyDistanceMapFit(f, config->distanceMap);
    if (height) config->distanceMap.viewpointHeight = *height;
    std::cout << "  viewpoint height " << fixedText(config->distanceMap.viewpointHeight, 3) << " m"
              << (height ? "" : " (kept; --height sets it)") << ": a ball seen at radius r lies at "
              << "distance(r) * (height - ball radius) / height\n";
    return save(*config, out);
}

// The samples: a --samples file, else the visible balls of the --input session's truth.csv.
struct BallInput {
    std::vector<BallSample> samples;
    std::string from;  // "24 marked balls in sessions/demo"
};

std::optional<BallInput> ballSamplesFromSession(const std::string& input, const Config& config, std::string& error)
{
    SessionOpen opened = SessionReader::open(input);
    if (!opened.ok()) {
        error = opened.error->toString() + " (ball-model reads the truth marks of a session, or give --samples)";
        return std::nullopt;
    }
    for (const auto& w : opened.reader->warnings()) std::cerr << "warning: " << w.toString() << "\n";
    const cv::Size size = opened.reader->frameSize();
    const cv::Size geometrySize(config.geometry.imageWidth, config.geometry.imageHeight);
    if (size != geometrySize) {
        error = "the config's geometry is for " + sizeText(geometrySize) + " frames but " + input + " holds " +
                sizeText(size) + " frames: run 'omnitune-calibrate rim' on it first";
        return std::nullopt;
    }
    const cv::Point2d centre(config.geometry.centerX, config.geometry.centerY);
    BallInput in{ballSamplesFromTruth(opened.reader->truth(), centre), ""};
    in.from = std::to_string(in.samples.size()) + " marked balls in " + input + ", measured from the centre " +
              pointText(centre);
    return in;
}

int runBallModel(const CommandLine& cl, const std::string& out)
{
    const auto samplesPath = cl.value("samples");
    if (!samplesPath && !cl.has("input"))
        return fail("ball-model needs --input SESSION with truth.csv, or --samples SAMPLES.csv (see --help)");
    std::optional<BallSamplesParse> file;
    if (samplesPath) {
        file = loadBallSamples(*samplesPath);
        for (const auto& w : file->warnings) std::cerr << "warning: " << w.toString() << "\n";
        if (!file->ok()) return fail(file->error->toString());
    }
    std::string error;
    auto config = startingConfig(cl, file && !file->needsDistanceMap(),
                                 file ? *samplesPath + " gives ground distances: they need the config's distance map"
                                      : "ball-model measures the marks from the mirror centre",
                                 error);
    if (!config) return fail(error);
    std::optional<BallInput> in;
    if (file) {
        in = BallInput{toBallSamples(file->rows, DistanceMap(config->distanceMap)), ""};
        in->from = std::to_string(in->samples.size()) + " samples from " + *samplesPath;
    } else {
        in = ballSamplesFromSession(*cl.value("input"), *config, error);
        if (!in) return fail(error);
    }

    const BallModelFitResult result = fitBallModel(in->samples);
    if (!result.ok()) return fail(result.error->toString());
    const BallModelFit& f = result.fit;
    const BallSample& worst = in->samples[std::size_t(f.worstSample)];
    std::cout << "ball-model: " << in->from << "; " << fixedText(f.minDistancePx) << ".." << fixedText(f.maxDistancePx)
              << " px out\n"
              << "  r(d) = " << ballCurveText(f.c0, f.c1, f.c2) << " px  (was "
              << ballCurveText(config->ball.c0, config->ball.c1, config->ball.c2) << ")\n"
              << "  residual RMS " << fixedText(f.rmsPx, 2) << " px, largest " << fixedText(f.maxAbsPx, 2) << " px ("
              << (worst.frame >= 0 ? "frame " + std::to_string(worst.frame) + ", " : std::string())
              << fixedText(worst.distancePx) << " px out, radius " << fixedText(worst.radiusPx, 2) << " px)\n";
    applyBallModelFit(f, config->ball);
    return save(*config, out);
}

// The imported mask's share of the ring, and a warning when it leaves most of it out.
void describeMask(const std::string& what, double processedShare)
{
    std::cout << "mask: " << what << "; " << fixedText(100.0 * processedShare, 1)
              << " % of the ring between inner_radius and outer_radius is processed\n";
    if (processedShare < kRingMostlyOffImageShare)
        std::cerr << "warning: the mask leaves most of the ring out: if the file means the other side, give --process "
                  << "the other colour\n";
}

int runMaskImport(const CommandLine& cl, const std::string& out)
{
    const std::string file = *cl.value("import");
    MaskConvention convention = MaskConvention::BrightProcesses;
    if (auto p = cl.value("process")) {
        if (*p == "black")
            convention = MaskConvention::DarkProcesses;
        else if (*p != "white")
            return fail("--process must be white or black, not '" + *p + "'");
    }
    std::string error;
    auto config = startingConfig(cl, false, "mask --import needs the camera's geometry", error);
    if (!config) return fail(error);
    cv::Mat image;
    if (const auto notRegular = checkRegularFile(file)) return fail(file + ": " + *notRegular);
    try {
        image = cv::imread(file, cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception&) {
        image.release();
    }
    if (image.empty()) return fail(file + ": cannot read it as an image");
    const MaskImportResult imported = importMask(image, convention, config->geometry);
    if (!imported.ok()) return fail(file + ": " + imported.error->toString());
    if (config->geometry.maskFile.empty()) config->geometry.maskFile = "mask.png";
    describeMask(file + " with " + (convention == MaskConvention::DarkProcesses ? "black" : "white") +
                     " = process, written as " + config->geometry.maskFile + " beside the config",
                 imported.fit.processedShare);
    config->mask = imported.fit.mask;
    return save(*config, out);
}

int runMask(const CommandLine& cl, const std::string& out)
{
    if (cl.has("import")) return runMaskImport(cl, out);
    if (!cl.has("auto")) return fail("mask needs --auto (from frames) or --import FILE (a mask made elsewhere)");
    if (!cl.has("input")) return fail("mask needs --input: a session or video in which the robot drives or turns");
    std::string error;
    auto in = framesForGeometry(cl, 16, "mask --auto judges pixels inside the mirror ring", error);
    if (!in) return fail(error);
    Config* config = &in->config;
    const FitFrames& frames = in->frames;

    StderrProgress progress("omnitune-calibrate mask");
    const AutoMaskResult mask = autoMask(frames.images, config->geometry, ColorLut(config->colors), {}, &progress);
    if (!mask.ok()) return fail(mask.error->toString());
    if (config->geometry.maskFile.empty()) config->geometry.maskFile = "mask.png";
    std::cout << "mask: " << mask.fit.frames << " frame(s) of " << in->source << "\n"
              << "  " << mask.fit.regions << " robot region(s), " << fixedText(100.0 * mask.fit.robotShare, 1)
              << " % of the mirror image; written as " << config->geometry.maskFile
              << " beside the config (white = process): check it in the window\n";
    config->mask = mask.fit.mask;
    return save(*config, out);
}

}  // namespace

int main(int argc, char** argv)
{
    quietOpenCvLogs();
    const std::string subcommand = argc > 1 ? argv[1] : "";
    // Options come after the subcommand; --help works in either place.
    const CommandLine cl = parseCommandLine(argc - 1, argv + 1, kOptions);
    if (subcommand == "--help" || subcommand == "-h" || cl.has("help")) {
        std::cout << usageText("omnitune-calibrate SUBCOMMAND", kSummary, kOptions);
        return 0;
    }
    if (subcommand != "rim" && subcommand != "colours" && subcommand != "distance-map" && subcommand != "ball-model" &&
        subcommand != "mask")
        return fail((subcommand.empty() ? std::string("no subcommand") : "unknown subcommand '" + subcommand + "'") +
                    ": rim, colours, distance-map, ball-model or mask (see --help)");
    if (!cl.error.empty()) return fail(cl.error + " (see --help)");
    if (wantsColourProfile(cl)) {
        if (subcommand != "colours") return fail("--profile-list, --profile-save and --profile-load go with colours");
        return runColourProfile(cl);
    }
    if (!cl.has("out")) return fail("--out OUT.yml is required (see --help)");
    const std::string out = *cl.value("out");
    try {
        if (subcommand == "rim") return runRim(cl, out);
        if (subcommand == "colours") return runColours(cl, out);
        if (subcommand == "distance-map") return runDistanceMap(cl, out);
        if (subcommand == "mask") return runMask(cl, out);
        return runBallModel(cl, out);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
