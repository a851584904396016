#include "calib/camera/ReplaySource.h"

namespace omnitune {

ReplaySource::ReplaySource(std::shared_ptr<const ReplayBuffer> buffer, std::string cameraDescription, cv::Size frameSize)
    : buffer_(std::move(buffer)), description_(std::move(cameraDescription)), size_(frameSize)
{
}

std::optional<FrameError> ReplaySource::readAt(int index, Frame& out)
{
    if (buffer_->find(index, out)) return std::nullopt;
    return FrameError{FrameErrorKind::OutOfRange, index, "",
                      "live frame " + std::to_string(index) + " of " + description_
                          + " has left the replay buffer (camera.replay_seconds)"};
}

}  // namespace omnitune
