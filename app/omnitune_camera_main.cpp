// omnitune-camera: a live camera on the command line (calib/camera/), for robots without a
// screen and for scripts. Opens --source (default: the first camera found), applies --config's
// camera section, --set features, runs the automatic calibration (--auto), records a session
// (--record DIR --seconds N) and writes the settings found into a config (--out, atomic with a
// backup). Errors are one line on stderr and a non-zero exit; --auto exits 0 only when it
// converged.
#include "app/CommandLine.h"
#include "calib/camera/CameraAutoCalibration.h"
#include "calib/camera/CameraCatalog.h"
#include "calib/camera/CameraRecording.h"
#include "calib/camera/CameraSettingsIo.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"
#include "core/Geometry.h"

#include <filesystem>
#include <iostream>

using namespace omnitune;

namespace {

const std::vector<OptionSpec> kOptions = {
    {"source", true, false, "SRC   dc1394[:GUID], v4l2[:DEVICE] or simulated (default: the config's\n"
                            "                          camera.source, else the first camera found)"},
    {"list", false, false, "      the cameras found and their features (with --source: that camera's)"},
    {"config", true, false, "FILE  apply this config's camera section when the camera opens; --auto uses its\n"
                            "                          camera_auto.* and geometry, --out starts from it"},
    {"set", true, true, "F=V   set feature F (exposure, gain, brightness, wb_u, wb_v, ...) to V; repeatable"},
    {"auto", false, false, "      automatic calibration of exposure, gain, white balance and brightness"},
    {"record", true, false, "DIR   record a session into DIR (new or empty), with the settings in session.yml"},
    {"seconds", true, false, "N     how long --record records (camera time; default 10)"},
    {"out", true, false, "FILE  write the camera's settings into a config (FILE.bak keeps the previous one)"},
    {"start", true, false, "STATE simulated camera: start good, dark, bright or tinted (default good)"},
    {"seed", true, false, "N     simulated camera: noise and tour seed (default 1)"},
    {"help", false, false, "      this text"},
};

int fail(const std::string& why)
{
    std::cerr << "omnitune-camera: " << why << "\n";
    return 1;
}

std::string settingsText(const CameraSettings& s)
{
    return "exposure=" + std::to_string(s.exposure) + " gain=" + std::to_string(s.gain) +
           " brightness=" + std::to_string(s.brightness) + " wb_blue=" + std::to_string(s.whiteBalanceBlue) +
           " wb_red=" + std::to_string(s.whiteBalanceRed);
}

void printFeatures(Camera& camera)
{
    std::cout << camera.description() << "\n";
    for (const CameraFeature& f : camera.features()) std::cout << "  " << describeCameraFeature(f) << "\n";
}

int list(const CommandLine& cl, const CameraOpen* opened)
{
    if (opened) {
        printFeatures(*opened->camera);
        return 0;
    }
    const CameraScan scan = listCameras();
    if (scan.cameras.empty()) std::cout << "no camera found\n";
    for (const std::string& note : scan.notes) std::cout << "  " << note << "\n";
    for (const CameraInfo& info : scan.cameras) {
        std::cout << info.source << "  " << info.name << "\n";
        CameraOpen cam = openCamera(info.source);
        if (cam.ok())
            for (const CameraFeature& f : cam.camera->features()) std::cout << "    " << describeCameraFeature(f) << "\n";
        else
            std::cout << "    (cannot open: " << cam.error->message << ")\n";
    }
    std::cout << "simulated  the simulated camera (--source simulated --start dark|bright|tinted)\n";
    (void)cl;
    return 0;
}

// "exposure=400" -> feature and value, or an error.
std::optional<std::string> parseSet(const std::string& text, CameraFeatureId& id, int& value)
{
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) return "--set " + text + ": expected FEATURE=VALUE, e.g. exposure=400";
    const auto f = parseCameraFeatureName(text.substr(0, eq));
    if (!f) return "--set " + text + ": unknown feature '" + text.substr(0, eq) + "' (features: " + cameraFeatureNames() + ")";
    const auto v = parseInt(text.substr(eq + 1));
    if (!v) return "--set " + text + ": '" + text.substr(eq + 1) + "' is not a whole number";
    id = *f;
    value = *v;
    return std::nullopt;
}

}  // namespace

int main(int argc, char** argv)
{
    const CommandLine cl = parseCommandLine(argc, argv, kOptions);
    if (cl.has("help")) {
        std::cout << usageText("omnitune-camera", "Opens a live camera: lists, sets, auto-calibrates, records.", kOptions);
        return 0;
    }
    if (!cl.error.empty()) return fail(cl.error + " (see --help)");
    if (cl.has("seconds") && !cl.has("record")) return fail("--seconds goes with --record DIR");

    // Everything the arguments say is checked before the camera is touched.
    std::vector<std::pair<CameraFeatureId, int>> sets;
    for (const std::string& s : cl.all("set")) {
        CameraFeatureId id{};
        int value = 0;
        if (auto why = parseSet(s, id, value)) return fail(*why);
        sets.emplace_back(id, value);
    }
    double seconds = 10.0;
    if (auto text = cl.value("seconds")) {
        const auto v = parseDouble(*text);
        if (!v || *v <= 0) return fail("--seconds must be a positive number of seconds, not '" + *text + "'");
        seconds = *v;
    }
    SimulatedCameraOptions sim;
    if (auto text = cl.value("start")) {
        const auto s = parseSimulatedStart(*text);
        if (!s) return fail("--start must be good, dark, bright or tinted, not '" + *text + "'");
        sim.start = *s;
    }
    if (auto text = cl.value("seed")) {
        const auto v = parseInt(*text);
        if (!v || *v < 0) return fail("--seed must be a whole number >= 0, not '" + *text + "'");
        sim.seed = unsigned(*v);
    }
    Config config;
    if (auto path = cl.value("config")) {
        ConfigLoad load = loadConfig(*path);
        for (const auto& w : load.warnings) std::cerr << "warning: " << w.toString() << "\n";
        if (!load.ok()) return fail(load.error->toString());
        config = load.config;
    }
    const std::string source = cl.value("source").value_or(config.camera.source);
    if ((cl.has("start") || cl.has("seed")) && source != "simulated")
        return fail("--start and --seed are for --source simulated");

    if (cl.has("list") && !cl.has("source")) return list(cl, nullptr);

    CameraOpen opened = openCamera(source, config.camera.frameRate, sim);
    if (!opened.ok()) return fail(opened.error->message);
    Camera& camera = *opened.camera;
    if (cl.has("list")) return list(cl, &opened);

    if (cl.has("config")) {
        const CameraSettingsApply applied = applyCameraSettings(camera, config.camera);
        if (applied.error) return fail(applied.error->message);
        for (const std::string& n : applied.notes) std::cerr << "note: " << n << "\n";
        std::cout << "applied the camera section of " << *cl.value("config") << ": "
                  << settingsText(readCameraSettings(camera)) << "\n";
    }
    for (const auto& [id, value] : sets) {
        std::string mismatch;
        if (auto err = setAndCheckFeature(camera, id, value, mismatch)) return fail(err->message);
        std::cout << cameraFeatureName(id) << " = " << value << "\n";
        if (!mismatch.empty()) std::cerr << "note: " << mismatch << "\n";
    }

    int status = 0;
    if (cl.has("auto")) {
        if (camera.frameSize() != Geometry(config.geometry, config.mask).imageSize())
            return fail("the camera gives " + std::to_string(camera.frameSize().width) + "x" +
                        std::to_string(camera.frameSize().height) + " frames but the config's geometry is for " +
                        std::to_string(config.geometry.imageWidth) + "x" + std::to_string(config.geometry.imageHeight));
        const cv::Mat used = Geometry(config.geometry, config.mask).usedMask();
        const CameraAutoResult r = runCameraAutoCalibration(camera, config.cameraAuto, used, [](const CameraAutoIteration& it) {
            std::cout << "iteration " << it.iteration << ": " << formatCameraMeasurement(it.measured) << " "
                      << settingsText(it.settings) << std::endl;
        });
        if (r.state == CameraAutoState::Converged) {
            std::cout << "converged: " << formatCameraMeasurement(r.last.measured) << " iterations=" << r.iterations << "\n";
        } else {
            std::cout << "not converged: " << r.reason << "\n";
            status = 1;
        }
    }
    if (auto dir = cl.value("record")) {
        const CameraRecordingResult rec = recordCamera(camera, *dir, seconds, {}, std::uint64_t(config.camera.recordMinFreeMb) * 1024 * 1024);
        std::cout << "recorded " << rec.frames << " frames to " << *dir << " (" << rec.dropped << " dropped)\n";
        if (rec.error) return fail(rec.error->c_str() + std::string(rec.frames > 0 ? " (the frames written are kept)" : ""));
    }
    if (auto out = cl.value("out"); out && status == 0) {
        config.camera = readCameraSettings(camera, config.camera);
        config.camera.source = source;
        const bool existed = std::filesystem::exists(*out);
        if (auto err = saveConfig(config, *out, true)) return fail(err->toString());
        std::cout << "wrote " << *out << (existed ? " (" + *out + ".bak keeps the file from before OmniTune first saved over it)" : "")
                  << "\n";
    }
    return status;
}
