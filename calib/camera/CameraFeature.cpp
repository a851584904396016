#include "calib/camera/CameraFeature.h"

namespace omnitune {

std::string_view cameraFeatureName(CameraFeatureId id)
{
    switch (id) {
    case CameraFeatureId::Exposure: return "exposure";
    case CameraFeatureId::Shutter: return "shutter";
    case CameraFeatureId::Gain: return "gain";
    case CameraFeatureId::Brightness: return "brightness";
    case CameraFeatureId::WhiteBalanceBlue: return "white_balance_blue";
    case CameraFeatureId::WhiteBalanceRed: return "white_balance_red";
    case CameraFeatureId::Gamma: return "gamma";
    case CameraFeatureId::Saturation: return "saturation";
    }
    return "?";
}

std::optional<CameraFeatureId> parseCameraFeatureName(std::string_view name)
{
    if (name == "wb_u") return CameraFeatureId::WhiteBalanceBlue;
    if (name == "wb_v") return CameraFeatureId::WhiteBalanceRed;
    for (CameraFeatureId id : kAllCameraFeatures)
        if (cameraFeatureName(id) == name) return id;
    return std::nullopt;
}

std::string cameraFeatureNames()
{
    std::string s;
    for (CameraFeatureId id : kAllCameraFeatures) s += (s.empty() ? "" : ", ") + std::string(cameraFeatureName(id));
    return s + " (wb_u, wb_v for the white balance)";
}

const CameraFeature* findCameraFeature(const std::vector<CameraFeature>& features, CameraFeatureId id)
{
    for (const CameraFeature& f : features)
        if (f.id == id) return &f;
    return nullptr;
}

std::string describeCameraFeature(const CameraFeature& f)
{
    return std::string(cameraFeatureName(f.id)) + " " + std::to_string(f.value) + " (" + std::to_string(f.min) + ".." +
           std::to_string(f.max) + (f.autoCapable ? (f.autoOn ? ", auto on" : ", auto off") : ", manual only") + ")";
}

}  // namespace omnitune
