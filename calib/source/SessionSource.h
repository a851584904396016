#pragma once
// A recorded session as a frame source: seekable, frame-accurate, with the camera settings
// from session.yml on every frame.
#include "calib/source/FrameSource.h"
#include "calib/session/SessionReader.h"

namespace omnitune {

class SessionSource : public FrameSource {
public:
    explicit SessionSource(SessionReader reader);

    // The reader, for the truth, the config and the warnings.
    const SessionReader& reader() const { return reader_; }

    std::string description() const override;
    bool isSeekable() const override { return true; }
    int frameCount() const override { return reader_.frameCount(); }
    cv::Size frameSize() const override { return reader_.frameSize(); }
    bool readsFile(const std::string& path) const override;

protected:
    std::optional<FrameError> readAt(int index, Frame& out) override;

private:
    SessionReader reader_;
};

}  // namespace omnitune
