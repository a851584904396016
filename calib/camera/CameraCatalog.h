#pragma once
// Which cameras there are and opening one by its --source text (also config camera.source):
//   "dc1394" | "dc1394:GUID"   an IIDC camera through libdc1394 (the first, or that GUID)
//   "v4l2" | "v4l2:DEVICE"     a V4L2 camera (the first capture device, or e.g. /dev/video1)
//   "simulated"                the simulated camera (SimulatedCameraOptions)
//   ""                         the first camera found: dc1394, then V4L2
// The camera comes back open; an error names the source and says what is missing.
#include "calib/camera/Camera.h"
#include "calib/camera/CameraInfo.h"
#include "calib/camera/SimulatedCamera.h"

#include <memory>
#include <string>

namespace omnitune {

// Every camera found (dc1394 first, then V4L2), with notes on backends that found none. The
// simulated camera is always there and is not listed.
CameraScan listCameras();

struct CameraOpen {
    std::unique_ptr<Camera> camera;  // open, when ok()
    std::optional<CameraError> error;

    bool ok() const { return camera != nullptr; }
};

// `frameRate` is asked of real cameras; `simulated` configures the simulated one.
CameraOpen openCamera(const std::string& source, double frameRate = 30.0, const SimulatedCameraOptions& simulated = {});

}  // namespace omnitune
