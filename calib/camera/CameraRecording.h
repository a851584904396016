#pragma once
// Recording a live camera into a session folder for a given time (omnitune-camera --record):
// grabs on the calling thread and hands every frame to a CameraRecorder, which writes it on
// its own thread and waits rather than drops when it falls behind (the camera itself keeps
// only its newest frames, so gaps in its frame index count as dropped). The camera's settings
// read back at the start are the session's camera snapshot (session.yml). An unplug ends the
// recording with the frames so far kept and the session closed. Stops after `seconds` of the
// camera's own time.
#include "calib/camera/Camera.h"

#include <cstdint>
#include <optional>
#include <string>

namespace omnitune {

struct CameraRecordingResult {
    int frames = 0;                    // written
    int dropped = 0;                   // frames the camera had that were not written
    std::optional<std::string> error;  // why it ended early or could not start; frames written stay
};

// `notes` goes into session.yml. The folder must be new or empty (SessionWriter's rules).
// `minFreeBytes`: stop when the disk has less free space (config camera.record_min_free_mb).
CameraRecordingResult recordCamera(Camera& camera, const std::string& folder, double seconds, const std::string& notes = {},
                                   std::uint64_t minFreeBytes = 0);

}  // namespace omnitune
