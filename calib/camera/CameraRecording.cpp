#include "calib/camera/CameraRecording.h"

#include "calib/camera/CameraSettingsIo.h"
#include "calib/session/SessionWriter.h"

namespace omnitune {

CameraRecordingResult recordCamera(Camera& camera, const std::string& folder, double seconds, const std::string& notes)
{
    CameraRecordingResult result;
    if (!camera.isStarted())
        if (auto err = camera.start()) {
            result.error = err->message;
            return result;
        }
    SessionInfo info;
    info.camera = readCameraSettings(camera);
    info.width = camera.frameSize().width;
    info.height = camera.frameSize().height;
    info.frameRate = info.camera.frameRate;
    info.notes = notes.empty() ? "recorded from " + camera.description() : notes;
    SessionCreate created = SessionWriter::create(folder, info);
    if (!created.ok()) {
        result.error = created.error->toString();
        return result;
    }
    SessionWriter& writer = *created.writer;
    int lastIndex = -1;
    double firstTime = -1;
    while (true) {
        Frame frame;
        if (auto err = camera.grab(frame)) {
            result.error = err->message;
            break;
        }
        if (firstTime < 0) firstTime = frame.timestampS;
        if (frame.timestampS - firstTime >= seconds) break;
        if (lastIndex >= 0) result.dropped += std::max(frame.index - lastIndex - 1, 0);
        lastIndex = frame.index;
        if (auto err = writer.appendFrame(frame.image)) {
            result.error = err->toString();
            break;
        }
        ++result.frames;
    }
    if (auto err = writer.finish(); err && !result.error) result.error = err->toString();
    return result;
}

}  // namespace omnitune
