#pragma once
// The replay buffer seen as a FrameSource: the window hands it to the pipeline's thread and
// asks for frames by their sequence number, while the camera itself stays on the GUI thread.
// Seekable with no known count; a frame that has left the ring is OutOfRange, with a message.
#include "calib/camera/ReplayBuffer.h"
#include "calib/source/FrameSource.h"

#include <memory>

namespace omnitune {

class ReplaySource : public FrameSource {
public:
    ReplaySource(std::shared_ptr<const ReplayBuffer> buffer, std::string cameraDescription, cv::Size frameSize);

    std::string description() const override { return description_; }
    bool isSeekable() const override { return true; }
    int frameCount() const override { return -1; }
    cv::Size frameSize() const override { return size_; }

protected:
    std::optional<FrameError> readAt(int index, Frame& out) override;

private:
    std::shared_ptr<const ReplayBuffer> buffer_;
    std::string description_;
    cv::Size size_;
};

}  // namespace omnitune
