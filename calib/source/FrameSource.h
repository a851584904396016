#pragma once
// Where frames come from: a recorded session, a video file, a folder of images, and later a
// live camera. Players and the GUI hold a FrameSource and never care which.
//
// Reading is one call, read(index, frame): seekable sources (sessions, images, video files)
// take any index in 0..frameCount()-1; every source takes FrameSource::kNext, the frame after
// the last one asked for (0 at first), so a player loop works on a live camera too:
//     Frame f;
//     while (true) {
//         const auto err = source.read(FrameSource::kNext, f);
//         if (err && err->kind == FrameErrorKind::OutOfRange) break;  // the end
//         if (err) { report(*err); continue; }                        // a bad frame: skip it
//         process(f);
//     }
// A failed read still moves kNext past the frame, so one bad file does not stall playback.
// A source is used from one thread at a time.
#include "calib/source/Frame.h"
#include "calib/source/FrameError.h"

#include <opencv2/core.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

class FrameSource {
public:
    static constexpr int kNext = -1;

    virtual ~FrameSource() = default;

    // "session /data/s1", "video clip.mp4", "images /data/run/*.png": for titles and messages.
    virtual std::string description() const = 0;
    // Random access by index is exact (see VideoSource for codecs where it is not).
    virtual bool isSeekable() const = 0;
    // Frames in the source; -1 when unknown (a live camera, a stream without a count).
    virtual int frameCount() const = 0;
    // The size every frame has; empty when not known before the first frame.
    virtual cv::Size frameSize() const = 0;

    // Fills `out` with frame `index` (or kNext) and returns nothing, or says why not; `out`
    // is unspecified after an error. Range and seekability are checked here, once for all
    // sources.
    std::optional<FrameError> read(int index, Frame& out);

    // The index kNext stands for now.
    int nextIndex() const { return next_; }

    // Whether `path` is a file this source reads (a frame, a video, a session's session.yml,
    // truth.csv or config), by identity on disk (sameFile), so a tool refuses to write onto
    // its own input.
    virtual bool readsFile(const std::string& path) const;

protected:
    // `index` is >= 0, below frameCount() when that is known, and equal to nextIndex() when the
    // source is not seekable. Sets everything in `out` but `index`.
    virtual std::optional<FrameError> readAt(int index, Frame& out) = 0;

private:
    int next_ = 0;
};

// Whether `a` and `b` are one existing file (same device and inode: links and "x/../x" count).
bool sameFile(const std::string& a, const std::string& b);

// What opening a source gives: the source, or an error naming the path and the fault; plus
// warnings about a source that opened but is not quite right (an interrupted session, ...).
template <class Source>
struct SourceOpen {
    std::unique_ptr<Source> source;     // set when ok()
    std::string error;                  // one line, names the path
    std::vector<std::string> warnings;  // one line each

    bool ok() const { return source != nullptr; }
};

}  // namespace omnitune
