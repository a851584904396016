#include "calib/camera/CameraSettingsIo.h"

namespace omnitune {

namespace {

constexpr CameraFeatureId kSettingsFeatures[] = {CameraFeatureId::Exposure, CameraFeatureId::Gain,
                                                 CameraFeatureId::Brightness, CameraFeatureId::WhiteBalanceBlue,
                                                 CameraFeatureId::WhiteBalanceRed};

}  // namespace

int* cameraSettingsField(CameraSettings& s, CameraFeatureId id)
{
    switch (id) {
    case CameraFeatureId::Exposure: return &s.exposure;
    case CameraFeatureId::Gain: return &s.gain;
    case CameraFeatureId::Brightness: return &s.brightness;
    case CameraFeatureId::WhiteBalanceBlue: return &s.whiteBalanceBlue;
    case CameraFeatureId::WhiteBalanceRed: return &s.whiteBalanceRed;
    default: return nullptr;
    }
}

std::optional<CameraError> setAndCheckFeature(Camera& camera, CameraFeatureId id, int value, std::string& mismatch)
{
    mismatch.clear();
    if (auto err = camera.setFeature(id, value)) return err;
    CameraFeature back;
    if (auto err = camera.readFeature(id, back)) return err;
    if (back.value != value)
        mismatch = std::string(cameraFeatureName(id)) + " is " + std::to_string(back.value) + ", asked for " + std::to_string(value);
    return std::nullopt;
}

CameraSettingsApply applyCameraSettings(Camera& camera, const CameraSettings& settings)
{
    CameraSettingsApply out;
    CameraSettings s = settings;
    const std::vector<CameraFeature> features = camera.features();
    for (CameraFeatureId id : kSettingsFeatures) {
        const CameraFeature* f = findCameraFeature(features, id);
        if (!f) {
            out.notes.push_back("the camera has no " + std::string(cameraFeatureName(id)) + ": camera." +
                                std::string(cameraFeatureName(id)) + " not applied");
            continue;
        }
        if (f->autoOn)
            if (auto err = camera.setAuto(id, false)) {
                out.error = err;
                return out;
            }
        std::string mismatch;
        if (auto err = setAndCheckFeature(camera, id, *cameraSettingsField(s, id), mismatch)) {
            out.error = err;
            return out;
        }
        if (!mismatch.empty()) out.notes.push_back(mismatch);
    }
    return out;
}

CameraSettings readCameraSettings(Camera& camera, CameraSettings base)
{
    for (const CameraFeature& f : camera.features())
        if (int* field = cameraSettingsField(base, f.id)) *field = f.value;
    return base;
}

}  // namespace omnitune
