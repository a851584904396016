#pragma once
// The adjustable features of a camera (IIDC names; V4L2 controls map onto them) and what a
// camera says about each: its range in the camera's own register units, the current value,
// and whether the camera can run it automatically.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace omnitune {

enum class CameraFeatureId {
    Exposure,          // IIDC EXPOSURE (auto-exposure reference); V4L2 exposure_absolute
    Shutter,           // IIDC SHUTTER (integration time)
    Gain,              // IIDC GAIN
    Brightness,        // IIDC BRIGHTNESS: the black level
    WhiteBalanceBlue,  // IIDC WHITE_BALANCE U/B
    WhiteBalanceRed,   // IIDC WHITE_BALANCE V/R
    Gamma,             // IIDC GAMMA
    Saturation,        // IIDC SATURATION
};

inline constexpr CameraFeatureId kAllCameraFeatures[] = {
    CameraFeatureId::Exposure,         CameraFeatureId::Shutter,         CameraFeatureId::Gain,
    CameraFeatureId::Brightness,       CameraFeatureId::WhiteBalanceBlue, CameraFeatureId::WhiteBalanceRed,
    CameraFeatureId::Gamma,            CameraFeatureId::Saturation,
};

struct CameraFeature {
    CameraFeatureId id = CameraFeatureId::Exposure;
    int min = 0;               // register units
    int max = 0;
    int value = 0;             // as read back from the camera
    bool autoCapable = false;  // the camera can run this feature itself
    bool autoOn = false;       // ... and does now
};

// "exposure", "shutter", "gain", "brightness", "white_balance_blue", "white_balance_red",
// "gamma", "saturation": the names of --set, --list and the config's camera section.
std::string_view cameraFeatureName(CameraFeatureId id);
// A name above or its short form "wb_u" / "wb_v"; nullopt for anything else.
std::optional<CameraFeatureId> parseCameraFeatureName(std::string_view name);
// "exposure, shutter, gain, ...": for messages that list what is accepted.
std::string cameraFeatureNames();

// The entry for `id` in `features`, or null.
const CameraFeature* findCameraFeature(const std::vector<CameraFeature>& features, CameraFeatureId id);

// "exposure 300 (0..4095, auto off)".
std::string describeCameraFeature(const CameraFeature& f);

}  // namespace omnitune
