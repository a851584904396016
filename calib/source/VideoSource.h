#pragma once
// A video file through cv::VideoCapture (FFmpeg or OpenCV's own MJPEG reader).
// Seeking sets CAP_PROP_POS_FRAMES, which some codecs honour only approximately (streams
// with B-frames or a variable frame rate can land a frame or two off), so reading the next
// frame in order never seeks: playing forward is always exact. For frame-accurate work on
// such footage, record a session instead.
#include "calib/source/FrameSource.h"

#include <opencv2/videoio.hpp>

namespace omnitune {

class VideoSource : public FrameSource {
public:
    static SourceOpen<VideoSource> open(const std::string& path);

    const std::string& path() const { return path_; }
    // Frames/s from the container; 0 when it does not say.
    double frameRate() const { return fps_; }

    std::string description() const override { return "video " + path_; }
    bool isSeekable() const override { return true; }
    // The container's count; -1 when it gives none (the end is found by reading).
    int frameCount() const override { return count_; }
    cv::Size frameSize() const override { return size_; }
    bool readsFile(const std::string& path) const override { return sameFile(path, path_); }

protected:
    std::optional<FrameError> readAt(int index, Frame& out) override;

private:
    VideoSource() = default;

    cv::VideoCapture capture_;
    std::string path_;
    int count_ = -1;
    double fps_ = 0.0;
    cv::Size size_;
    int position_ = 0;  // the frame the next capture_.read() returns; -1 unknown
};

}  // namespace omnitune
