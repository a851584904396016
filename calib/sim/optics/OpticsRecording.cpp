#include "calib/sim/optics/OpticsRecording.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace omnitune {

std::string opticsCellNotes(const OpticsCell& cell, const MeasuredCalibration& cal)
{
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "optics simulator (omnitune-sim --optics), seed %u: ball %s, light %s, distractors %s, carpet %s, "
                  "mirror %s, %dx%d%s.\n"
                  "config.yml is fitted from measurements/ (rim centre %.2f,%.2f, ring %.1f..%.1f px, distance map "
                  "%s rms %.1f cm over the marks, ball model rms %.2f px), never from the simulator's truth.",
                  cell.seed, std::string(ballKindName(cell.ball)).c_str(), opticsLightName(cell.light).c_str(),
                  opticsDistractorsName(cell.distractors).c_str(), opticsCarpetName(cell.carpet).c_str(),
                  opticsMirrorName(cell.mirror).c_str(), cell.image.width, cell.image.height,
                  cell.ballPresent ? "" : ", no ball", cal.rim.centre.x, cal.rim.centre.y,
                  cal.config.geometry.innerRadius, cal.config.geometry.outerRadius,
                  cal.distanceMapFromRings ? "from the mark rings" : "polynomial", cal.distanceMapRmsCm,
                  cal.ballModel.rmsPx);
    return buf;
}

OpticsRecordingResult recordOpticsSession(const std::string& folder, const OpticsCell& cell, const Config& base,
                                          const SessionWriterOptions& writerOptions, Progress* progress)
{
    OpticsRecordingResult result;
    const OpticsCamera cam = opticsCellCamera(cell, base);
    if (!cam.calibration->ok()) {
        result.error = "the calibration from the measurements failed: " + *cam.calibration->error;
        return result;
    }
    const Config& config = cam.calibration->config;
    SessionInfo info;
    info.camera = config.camera;
    info.camera.model = "omnitune-sim --optics";
    info.width = cell.image.width;
    info.height = cell.image.height;
    info.frameRate = config.camera.frameRate;
    info.notes = opticsCellNotes(cell, *cam.calibration);
    SessionCreate created = SessionWriter::create(folder, info, writerOptions);
    if (!created.ok()) {
        result.error = created.error->toString();
        return result;
    }
    SessionWriter& writer = *created.writer;
    if (auto issue = writer.writeConfig(config)) {
        result.error = issue->toString();
        return result;
    }
    const std::string measured = (std::filesystem::path(folder) / "measurements").string();
    if (auto e = saveCameraMeasurements(*cam.measurements, measured)) {
        result.error = *e;
        return result;
    }
    {
        std::ofstream out(std::filesystem::path(measured) / "ball_samples.csv");
        out << ballSamplesCsv(cam.calibration->ballSamples);
    }
    for (int i = 0; i < cell.frames; ++i) {
        if (progress && progress->isCancelRequested()) {
            result.cancelled = true;
            break;
        }
        const OpticsScene scene = opticsCellScene(cell, i, *cam.renderer);
        OpticsTruth truth;
        const cv::Mat frame = cam.renderer->render(scene, &truth);
        const TruthRow row = toTruthRow(truth, i, cell.ballPresent);
        if (auto issue = writer.appendFrame(frame, row)) {
            result.error = issue->toString();
            return result;
        }
        ++result.frames;
        result.visibleBalls += row.ballVisible ? 1 : 0;
        if (progress) progress->update(100.0 * (i + 1) / cell.frames);
    }
    if (auto issue = writer.finish()) result.error = issue->toString();
    return result;
}

}  // namespace omnitune
