#pragma once
// An IIDC (FireWire) camera through libdc1394, as the thesis' robots used (Point Grey Flea2):
// 640x480 YUV 4:2:2 (UYVY) or RGB8, Format7 when the camera offers no fixed 640x480 mode, the
// configured frame rate (nearest fixed rate), ISO 400 (800 when the camera runs 1394b), DMA
// capture into a small ring of which grab() takes the newest frame. UYVY is converted with
// core's convertUyvyToBgr: libdc1394's own full-range BT.601, which is what IIDC cameras send
// (not cv::cvtColor's video range; see docs/cameras.md). Features: exposure, shutter, gain,
// brightness, white balance U/B and V/R, gamma, saturation, manual or auto. A camera that stops
// answering (unplugged) makes grab() return CameraErrorKind::Unplugged; open() again reconnects.
// No FireWire bus or no camera: open() returns NoDevice with a message, never a crash.
#include "calib/camera/Camera.h"
#include "calib/camera/CameraInfo.h"

#include <cstdint>
#include <optional>

namespace omnitune {

struct Dc1394Options {
    double frameRate = 30.0;  // frames/s; the nearest fixed rate the mode offers
    int ringBuffers = 4;      // DMA ring size: small, so the newest frame is never old
};

class Dc1394Camera : public Camera {
public:
    // `guid`: the camera to open; nullopt opens the first one found.
    explicit Dc1394Camera(std::optional<std::uint64_t> guid = std::nullopt, const Dc1394Options& options = {});
    ~Dc1394Camera() override;

    std::string description() const override;
    std::optional<CameraError> open() override;
    std::optional<CameraError> start() override;
    std::optional<CameraError> grab(Frame& out) override;
    void stop() override;
    void close() override;
    bool isOpen() const override { return camera_ != nullptr; }
    bool isStarted() const override { return started_; }
    cv::Size frameSize() const override { return size_; }
    std::vector<CameraFeature> features() override;

protected:
    std::optional<CameraError> writeFeature(CameraFeatureId id, int value) override;
    std::optional<CameraError> writeAuto(CameraFeatureId id, bool on) override;

private:
    std::optional<std::uint64_t> guid_;
    Dc1394Options options_;
    void* context_ = nullptr;  // dc1394_t
    void* camera_ = nullptr;   // dc1394camera_t
    std::string name_;
    cv::Size size_;
    int mode_ = 0;             // dc1394video_mode_t
    bool started_ = false;
    // What frames report as their settings: read at start() and after every write (reading the
    // camera's registers every frame would cost bus time at 30 frames/s).
    CameraSettings settings_;
    void refreshSettings();
    int index_ = 0;
    double firstTimestampUs_ = -1;
};

// The IIDC cameras on the FireWire bus, or a note why there are none.
CameraScan listDc1394Cameras();

// "0x00b09d0100a01a9a" <-> GUID; nullopt for text that is not a 64-bit hex number.
std::string formatGuid(std::uint64_t guid);
std::optional<std::uint64_t> parseGuid(const std::string& text);

}  // namespace omnitune
