#include "calib/source/FrameSource.h"

#include <filesystem>

namespace omnitune {

std::optional<FrameError> FrameSource::read(int index, Frame& out)
{
    if (index == kNext) index = next_;
    const int count = frameCount();
    if (index < 0 || (count >= 0 && index >= count)) {
        const std::string range = count == 0  ? "it holds none"
                                  : count > 0 ? "frames are 0.." + std::to_string(count - 1)
                                              : "frames are 0 and up";
        return FrameError{FrameErrorKind::OutOfRange, index, "",
                          description() + ": no frame " + std::to_string(index) + " (" + range + ")"};
    }
    if (!isSeekable() && index != next_)
        return FrameError{FrameErrorKind::NotSeekable, index, "",
                          description() + " plays only forward: frame " + std::to_string(next_) +
                              " comes next, not " + std::to_string(index)};
    next_ = index + 1;
    auto err = readAt(index, out);
    if (err) {
        err->index = index;
        return err;
    }
    out.index = index;
    return std::nullopt;
}

bool FrameSource::readsFile(const std::string&) const { return false; }

bool sameFile(const std::string& a, const std::string& b)
{
    std::error_code ec;
    return !a.empty() && !b.empty() && std::filesystem::equivalent(a, b, ec) && !ec;
}

}  // namespace omnitune
