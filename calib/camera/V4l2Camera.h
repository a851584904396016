#pragma once
// A USB (UVC) camera through the V4L2 API (linux/videodev2.h): 640x480 YUYV or UYVY at the
// configured rate, four mmap'ed buffers of which grab() takes the newest. Features map onto
// the driver's controls where it has them: exposure (exposure_absolute, auto through
// exposure_auto), gain (autogain), brightness, white balance U/B and V/R (blue_balance,
// red_balance, auto_white_balance), gamma, saturation; a control the driver lacks is simply not
// listed. YUYV from UVC cameras is video-range BT.601 and is converted with cv::cvtColor.
// No such device: open() returns NoDevice; a device that goes away while streaming (ENODEV)
// makes grab() return Unplugged.
#include "calib/camera/Camera.h"
#include "calib/camera/CameraInfo.h"

#include <string>
#include <vector>

namespace omnitune {

class V4l2Camera : public Camera {
public:
    // `device`: "/dev/video0"; empty opens the first capture device found.
    explicit V4l2Camera(std::string device = {}, double frameRate = 30.0);
    ~V4l2Camera() override;

    std::string description() const override;
    std::optional<CameraError> open() override;
    std::optional<CameraError> start() override;
    std::optional<CameraError> grab(Frame& out) override;
    void stop() override;
    void close() override;
    bool isOpen() const override { return fd_ >= 0; }
    bool isStarted() const override { return started_; }
    cv::Size frameSize() const override { return size_; }
    std::vector<CameraFeature> features() override;

protected:
    std::optional<CameraError> writeFeature(CameraFeatureId id, int value) override;
    std::optional<CameraError> writeAuto(CameraFeatureId id, bool on) override;

private:
    struct Buffer {
        void* start = nullptr;
        std::size_t length = 0;
    };
    std::optional<CameraError> unplugged(const std::string& what);

    std::string device_;
    double frameRate_ = 30.0;
    int fd_ = -1;
    std::string card_;
    cv::Size size_;
    unsigned pixelFormat_ = 0;
    std::vector<Buffer> buffers_;
    bool started_ = false;
    // What frames report as their settings: read at start() and after every write (reading the
    // camera's registers every frame would cost bus time at 30 frames/s).
    CameraSettings settings_;
    void refreshSettings();
    int index_ = 0;
    double firstTimestampS_ = -1;
};

// The V4L2 capture devices (/dev/video*), or a note why there are none.
CameraScan listV4l2Cameras();

}  // namespace omnitune
