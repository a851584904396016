#pragma once
// The config's camera section (core/CameraSettings.h) and a live camera: writing the settings
// when the camera opens (the camera's own auto modes off for them, so the image does not drift
// during a match) and reading back what the camera holds.
#include "calib/camera/Camera.h"
#include "core/CameraSettings.h"

#include <string>
#include <vector>

namespace omnitune {

// The register of `settings` that feature `id` stands for; null for a feature the section has not.
int* cameraSettingsField(CameraSettings& settings, CameraFeatureId id);

struct CameraSettingsApply {
    std::vector<std::string> notes;   // features the camera lacks, values it holds differently ("exposure is 410, asked for 400")
    std::optional<CameraError> error; // the first write the camera refused; the rest were not tried
};

// Writes exposure, gain, brightness and white balance of `settings` (turning those features'
// auto modes off) and reads each back.
CameraSettingsApply applyCameraSettings(Camera& camera, const CameraSettings& settings);

// `base` with the features the camera has replaced by their read-back values.
CameraSettings readCameraSettings(Camera& camera, CameraSettings base = {});

// Writes one feature and reads it back: nothing, or "exposure is 410, asked for 400" when the
// camera holds another value.
std::optional<CameraError> setAndCheckFeature(Camera& camera, CameraFeatureId id, int value, std::string& mismatch);

}  // namespace omnitune
