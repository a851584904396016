#include "calib/camera/CameraFrameSource.h"

namespace omnitune {

CameraFrameSource::CameraFrameSource(std::unique_ptr<Camera> camera) : camera_(std::move(camera)) {}

std::string CameraFrameSource::description() const { return camera_->description(); }

cv::Size CameraFrameSource::frameSize() const { return camera_->frameSize(); }

std::optional<FrameError> CameraFrameSource::readAt(int index, Frame& out)
{
    const auto deviceError = [&](const CameraError& e) {
        return FrameError{FrameErrorKind::Device, index, "", e.message};
    };
    if (!camera_->isStarted())
        if (auto err = camera_->start()) return deviceError(*err);
    if (auto err = camera_->grab(out)) return deviceError(*err);
    lastCameraIndex_ = out.index;
    return std::nullopt;
}

}  // namespace omnitune
