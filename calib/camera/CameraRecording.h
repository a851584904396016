#pragma once
// Recording a live camera into a session folder (calib/session/SessionWriter): every grabbed
// frame is written as it comes, with the camera's settings read back at the start as the
// session's camera snapshot (session.yml). Frames the camera dropped while a frame was being
// written are counted from the gaps in its frame index. An unplug ends the recording with the
// frames so far kept and the session closed. Stops after `seconds` of the camera's own time.
#include "calib/camera/Camera.h"

#include <optional>
#include <string>

namespace omnitune {

struct CameraRecordingResult {
    int frames = 0;                    // written
    int dropped = 0;                   // frames the camera had that were not written
    std::optional<std::string> error;  // why it ended early or could not start; frames written stay
};

// `notes` goes into session.yml. The folder must be new or empty (SessionWriter's rules).
CameraRecordingResult recordCamera(Camera& camera, const std::string& folder, double seconds, const std::string& notes = {});

}  // namespace omnitune
