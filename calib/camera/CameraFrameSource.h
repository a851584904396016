#pragma once
// A live camera seen as a FrameSource, so the window, the player and the tools read from it
// like from a session: frameCount() is -1 and it only plays forward (kNext). Each read grabs
// the camera's newest frame; a camera error becomes a FrameErrorKind::Device error with the
// camera's message. The camera is started on the first read when it is not yet.
#include "calib/camera/Camera.h"
#include "calib/source/FrameSource.h"

#include <memory>

namespace omnitune {

class CameraFrameSource : public FrameSource {
public:
    // `camera` must be open.
    explicit CameraFrameSource(std::unique_ptr<Camera> camera);

    std::string description() const override;
    bool isSeekable() const override { return false; }
    int frameCount() const override { return -1; }
    cv::Size frameSize() const override;

    Camera& camera() { return *camera_; }
    // The camera's own index of the last frame read (gaps are frames the camera dropped).
    int lastCameraIndex() const { return lastCameraIndex_; }

protected:
    std::optional<FrameError> readAt(int index, Frame& out) override;

private:
    std::unique_ptr<Camera> camera_;
    int lastCameraIndex_ = -1;
};

}  // namespace omnitune
