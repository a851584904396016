#include "calib/camera/CameraRecording.h"

#include "calib/camera/CameraRecorder.h"

namespace omnitune {

CameraRecordingResult recordCamera(Camera& camera, const std::string& folder, double seconds, const std::string& notes,
                                   std::uint64_t minFreeBytes)
{
    CameraRecordingResult result;
    if (!camera.isStarted())
        if (auto err = camera.start()) {
            result.error = err->message;
            return result;
        }
    CameraRecorderOptions options;
    options.notes = notes;
    options.minFreeBytes = minFreeBytes;
    CameraRecorder::Start started = CameraRecorder::start(camera, folder, options);
    if (!started.ok()) {
        result.error = started.error;
        return result;
    }
    CameraRecorder& recorder = *started.recorder;
    double firstTime = -1;
    while (true) {
        Frame frame;
        if (auto err = camera.grab(frame)) {
            result.error = err->message;
            break;
        }
        if (firstTime < 0) firstTime = frame.timestampS;
        if (frame.timestampS - firstTime >= seconds) break;
        if (!recorder.push(frame, true)) break;  // stopped by itself: the status says why
    }
    const CameraRecorderStatus status = recorder.finish();
    result.frames = status.written;
    result.dropped = status.dropped;
    if (!result.error) result.error = status.error;
    return result;
}

}  // namespace omnitune
