#pragma once
// Why a camera call failed: a kind the caller can act on (offer a reconnect after an unplug,
// clamp a value) plus a message for the user that names the camera.
#include <string>
#include <string_view>

namespace omnitune {

enum class CameraErrorKind {
    NoDevice,            // no such camera, no bus, no driver: nothing to open
    Unplugged,           // the camera went away while open
    FeatureUnsupported,  // this camera has no such feature (or no auto mode for it)
    ValueOutOfRange,     // a value outside the feature's min..max
    NotStarted,          // grab() before start(), or a call on a closed camera
    Device,              // the driver or the bus refused (mode, DMA, a timeout)
};

inline std::string_view cameraErrorKindName(CameraErrorKind k)
{
    switch (k) {
    case CameraErrorKind::NoDevice: return "no device";
    case CameraErrorKind::Unplugged: return "unplugged";
    case CameraErrorKind::FeatureUnsupported: return "feature unsupported";
    case CameraErrorKind::ValueOutOfRange: return "value out of range";
    case CameraErrorKind::NotStarted: return "not started";
    case CameraErrorKind::Device: return "device";
    }
    return "?";
}

struct CameraError {
    CameraErrorKind kind = CameraErrorKind::Device;
    std::string message;  // one line; names the camera

    std::string toString() const { return message; }
};

}  // namespace omnitune
