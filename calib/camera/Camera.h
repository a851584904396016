#pragma once
// One live camera, whatever drives it (libdc1394, V4L2, the simulated camera):
//     open() -> start() -> grab() ... -> stop() -> close()
// with its features listed, set and read back at any time while open. Every call returns
// nothing or a CameraError; feature writes are checked here, once for all cameras (the
// feature exists, the value is in range), before a driver sees them. A camera is used from one
// thread at a time. grab() hands out the newest frame the camera has, dropping older ones, so a
// slow reader never falls behind; Frame::index counts the camera's frames, so a gap says how
// many were dropped.
#include "calib/camera/CameraError.h"
#include "calib/camera/CameraFeature.h"
#include "calib/source/Frame.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

class Camera {
public:
    virtual ~Camera() = default;

    // "simulated camera (dark start, seed 1)", "dc1394 camera 0x00b09d0100a01a9a (Point Grey Flea2)".
    virtual std::string description() const = 0;

    virtual std::optional<CameraError> open() = 0;
    virtual std::optional<CameraError> start() = 0;
    // The newest frame: BGR, with its timestamp (s since start()) and the settings in effect
    // when the source knows them. Waits for one at most about a second.
    virtual std::optional<CameraError> grab(Frame& out) = 0;
    virtual void stop() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual bool isStarted() const = 0;
    // Frame size of the chosen mode; empty before open().
    virtual cv::Size frameSize() const = 0;

    // The features this camera has, with their current values read back.
    virtual std::vector<CameraFeature> features() = 0;

    // Sets `id` to `value` (and turns the feature's auto mode off). Refused with
    // FeatureUnsupported / ValueOutOfRange before the driver is asked.
    std::optional<CameraError> setFeature(CameraFeatureId id, int value);
    // Turns the camera's own automatic mode for `id` on or off.
    std::optional<CameraError> setAuto(CameraFeatureId id, bool on);
    // Reads `id` back from the camera.
    std::optional<CameraError> readFeature(CameraFeatureId id, CameraFeature& out);

protected:
    // `id` exists and `value` is in its range; the camera is open.
    virtual std::optional<CameraError> writeFeature(CameraFeatureId id, int value) = 0;
    // `id` exists and is auto-capable (when `on`); the camera is open.
    virtual std::optional<CameraError> writeAuto(CameraFeatureId id, bool on) = 0;

    CameraError error(CameraErrorKind kind, const std::string& what) const
    {
        return CameraError{kind, description() + ": " + what};
    }
};

}  // namespace omnitune
