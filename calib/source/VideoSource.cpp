#include "calib/source/VideoSource.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio/registry.hpp>

#include <filesystem>

namespace omnitune {

SourceOpen<VideoSource> VideoSource::open(const std::string& path)
{
    SourceOpen<VideoSource> out;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        out.error = path + ": no such file";
        return out;
    }
    std::unique_ptr<VideoSource> v(new VideoSource);
    v->path_ = path;
    // Only the backends that decode files: CAP_ANY would also try V4L2, image sequences and
    // gphoto2 (which scans USB) on any path it is given.
    // Not GStreamer: it adds no file format FFmpeg lacks, and prints GLib criticals on stderr
    // that would break the tools' one-line errors.
    for (const cv::VideoCaptureAPIs api : {cv::CAP_FFMPEG, cv::CAP_OPENCV_MJPEG}) {
        if (!cv::videoio_registry::hasBackend(api)) continue;
        try {
            if (v->capture_.open(path, api)) break;
        } catch (const cv::Exception&) {
        }
        v->capture_.release();
    }
    if (!v->capture_.isOpened()) {
        out.error = path + ": cannot be opened as a video (neither FFmpeg nor OpenCV's MJPEG reader can read it)";
        return out;
    }
    const double count = v->capture_.get(cv::CAP_PROP_FRAME_COUNT);
    v->count_ = count >= 1 ? int(count) : -1;
    v->fps_ = std::max(0.0, v->capture_.get(cv::CAP_PROP_FPS));
    v->size_ = cv::Size(int(v->capture_.get(cv::CAP_PROP_FRAME_WIDTH)), int(v->capture_.get(cv::CAP_PROP_FRAME_HEIGHT)));
    out.source = std::move(v);
    return out;
}

std::optional<FrameError> VideoSource::readAt(int index, Frame& out)
{
    auto fail = [&](FrameErrorKind kind, const std::string& message) {
        position_ = -1;  // the capture is somewhere unknown now: seek next time
        return FrameError{kind, index, path_, message};
    };
    if (index != position_) {
        bool moved = false;
        try {
            moved = capture_.set(cv::CAP_PROP_POS_FRAMES, index);
        } catch (const cv::Exception&) {
        }
        if (!moved) return fail(FrameErrorKind::Unreadable, path_ + ": cannot seek to frame " + std::to_string(index));
        position_ = index;
    }
    cv::Mat image;  // fresh each time: a frame the caller keeps is never overwritten
    bool got = false;
    try {
        got = capture_.read(image) && !image.empty();
    } catch (const cv::Exception&) {
    }
    if (!got)
        // With a known count the base class stops at the end, so a failure inside is a bad frame.
        return count_ < 0
                   ? fail(FrameErrorKind::OutOfRange, path_ + " ends before frame " + std::to_string(index))
                   : fail(FrameErrorKind::Unreadable, path_ + ": cannot decode frame " + std::to_string(index));
    position_ = index + 1;
    if (image.type() == CV_8UC1) cv::cvtColor(image, image, cv::COLOR_GRAY2BGR);
    else if (image.type() == CV_8UC4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
    if (image.type() != CV_8UC3)
        return fail(FrameErrorKind::Unreadable,
                    path_ + ": frame " + std::to_string(index) + " decodes as " + cv::typeToString(image.type()) +
                        ", not 8-bit BGR");
    if (size_.empty()) size_ = image.size();
    if (image.size() != size_)
        return fail(FrameErrorKind::WrongSize, path_ + ": frame " + std::to_string(index) + " is " +
                                                   std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                                                   ", the video's first frames are " + std::to_string(size_.width) +
                                                   "x" + std::to_string(size_.height));
    out.image = image;
    out.format = PixelFormat::Bgr8;
    out.timestampS = fps_ > 0.0 ? index / fps_ : capture_.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
    out.camera.reset();
    return std::nullopt;
}

}  // namespace omnitune
