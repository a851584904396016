#include "calib/source/SessionSource.h"

namespace omnitune {

SessionSource::SessionSource(SessionReader reader) : reader_(std::move(reader)) {}

std::string SessionSource::description() const { return "session " + reader_.folder(); }

std::optional<FrameError> SessionSource::readAt(int index, Frame& out)
{
    cv::Mat image;
    if (auto err = reader_.readFrame(index, image)) return err;
    out.image = image;
    out.format = PixelFormat::Bgr8;  // frames are stored as BGR whatever the camera delivered
    out.timestampS = reader_.timestampOf(index);
    out.camera = reader_.hasInfoFile() ? std::optional<CameraSettings>(reader_.info().camera) : std::nullopt;
    return std::nullopt;
}

}  // namespace omnitune
