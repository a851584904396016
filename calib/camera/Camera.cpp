#include "calib/camera/Camera.h"

namespace omnitune {

std::optional<CameraError> Camera::readFeature(CameraFeatureId id, CameraFeature& out)
{
    if (!isOpen()) return error(CameraErrorKind::NotStarted, "the camera is not open");
    const std::vector<CameraFeature> all = features();
    const CameraFeature* f = findCameraFeature(all, id);
    if (!f) return error(CameraErrorKind::FeatureUnsupported, "has no " + std::string(cameraFeatureName(id)));
    out = *f;
    return std::nullopt;
}

std::optional<CameraError> Camera::setFeature(CameraFeatureId id, int value)
{
    CameraFeature f;
    if (auto err = readFeature(id, f)) return err;
    if (value < f.min || value > f.max)
        return error(CameraErrorKind::ValueOutOfRange,
                     std::string(cameraFeatureName(id)) + " " + std::to_string(value) + " is outside its range " +
                         std::to_string(f.min) + ".." + std::to_string(f.max));
    return writeFeature(id, value);
}

std::optional<CameraError> Camera::setAuto(CameraFeatureId id, bool on)
{
    CameraFeature f;
    if (auto err = readFeature(id, f)) return err;
    if (on && !f.autoCapable)
        return error(CameraErrorKind::FeatureUnsupported,
                     std::string(cameraFeatureName(id)) + " has no automatic mode on this camera");
    return writeAuto(id, on);
}

}  // namespace omnitune
