#include "calib/sim/TourRecording.h"

#include "calib/sim/SceneSimulator.h"

namespace omnitune {

std::string tourNotes(const TourRecordingOptions& o)
{
    const TourOptions& t = o.tour;
    return "omnitune-sim: ball " + std::string(ballKindName(t.ball)) + (o.ballPresent ? "" : " (left out)") + ", " +
           std::to_string(t.frames) + " frames, seed " + std::to_string(t.seed) + (t.shadow ? ", head shadow" : "") +
           (t.feet ? ", feet" : "") + (t.obstacles ? "" : ", no obstacles") +
           (o.motionBlurPx > 0 ? ", motion blur " + std::to_string(o.motionBlurPx) + " px" : "") +
           (o.occlusion > 0 ? ", occlusion " + std::to_string(o.occlusion) : "");
}

TourRecordingResult recordTour(const std::string& folder, const Config& config, const TourRecordingOptions& options,
                               Progress* progress)
{
    TourRecordingResult out;
    const SceneSimulator sim(config);
    std::vector<SceneOptions> scenes = makeTour(options.tour);
    SessionInfo info;
    info.camera = config.camera;
    info.camera.model = "omnitune-sim";
    info.width = config.geometry.imageWidth;
    info.height = config.geometry.imageHeight;
    info.frameRate = config.camera.frameRate;
    info.notes = tourNotes(options);
    SessionCreate created = SessionWriter::create(folder, info, options.writer);
    if (!created.ok()) {
        out.error = created.error;
        return out;
    }
    SessionWriter& writer = *created.writer;
    if ((out.error = writer.writeConfig(config))) return out;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        if (progress && progress->isCancelRequested()) {
            out.cancelled = true;
            break;
        }
        SceneOptions& scene = scenes[i];
        scene.ballPresent = options.ballPresent;
        scene.motionBlurPx = options.motionBlurPx;
        scene.occlusion = options.occlusion;
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
        if ((out.error = writer.appendFrame(image, row))) return out;
        ++out.frames;
        if (progress) progress->update(100.0 * double(i + 1) / double(scenes.size()));
    }
    out.error = writer.finish();
    return out;
}

}  // namespace omnitune
