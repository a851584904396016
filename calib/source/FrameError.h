#pragma once
// Why a frame source could not deliver a frame: a kind the caller can act on (stop at the
// end, skip a bad frame) plus the file and a message for the user.
#include <string>
#include <string_view>

namespace omnitune {

enum class FrameErrorKind {
    OutOfRange,   // no frame at that index: before the first, or at or past the end of the source
    NotSeekable,  // a random access on a source that only plays forward
    Missing,      // the frame's file is not there
    Unreadable,   // the file or stream is there but does not decode
    WrongSize,    // the frame's size differs from the source's
    Device,       // the camera or stream failed
};

inline std::string_view frameErrorKindName(FrameErrorKind k)
{
    switch (k) {
    case FrameErrorKind::OutOfRange: return "out of range";
    case FrameErrorKind::NotSeekable: return "not seekable";
    case FrameErrorKind::Missing: return "missing";
    case FrameErrorKind::Unreadable: return "unreadable";
    case FrameErrorKind::WrongSize: return "wrong size";
    case FrameErrorKind::Device: return "device";
    }
    return "?";
}

struct FrameError {
    FrameErrorKind kind = FrameErrorKind::Unreadable;
    int index = -1;       // the frame asked for
    std::string file;     // the file at fault (a frame PNG, the video, ...); may be empty
    std::string message;  // what is wrong, in words; names the file

    std::string toString() const { return message; }
};

}  // namespace omnitune
