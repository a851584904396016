#include "calib/source/SessionSource.h"

#include <filesystem>

namespace omnitune {

SessionSource::SessionSource(SessionReader reader) : reader_(std::move(reader)) {}

bool SessionSource::readsFile(const std::string& path) const
{
    namespace fs = std::filesystem;
    const fs::path dir(reader_.folder());
    for (const fs::path& own : {dir / kSessionInfoFile, dir / kSessionTruthFile, fs::path(reader_.configPath())})
        if (sameFile(path, own.string())) return true;
    // Anything in frames/, not only the frames counted: a stray file there is still the session's.
    std::error_code ec;
    return fs::exists(path, ec) && sameFile(fs::path(path).parent_path().string(), (dir / kSessionFramesDir).string());
}

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
