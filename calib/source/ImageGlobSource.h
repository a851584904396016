#pragma once
// Still images as a frame source: every image in a folder, the files a pattern such as
// "run/*.png" or "run/frame_??.jpg" matches, or one image file. Files play in natural order
// (frame2 before frame10), the order people number them in.
#include "calib/source/FrameSource.h"

#include <string>
#include <vector>

namespace omnitune {

struct ImageGlobOptions {
    // frames/s assumed for the timestamps (image files carry none), > 0.
    double frameRate = 30.0;
};

class ImageGlobSource : public FrameSource {
public:
    // `pattern`: a folder, a glob with * ? [...] in the file name only (not in the folders),
    // or an image file. Only files with an image extension count (isImageFileName). Fails
    // when nothing matches or no matching file decodes; the first file that decodes sets the
    // size every frame must have.
    static SourceOpen<ImageGlobSource> open(const std::string& pattern, const ImageGlobOptions& options = {});

    // Full paths in play order.
    const std::vector<std::string>& files() const { return files_; }

    std::string description() const override { return "images " + pattern_; }
    bool isSeekable() const override { return true; }
    int frameCount() const override { return int(files_.size()); }
    bool readsFile(const std::string& path) const override;
    cv::Size frameSize() const override { return size_; }

protected:
    std::optional<FrameError> readAt(int index, Frame& out) override;

private:
    ImageGlobSource() = default;

    std::string pattern_;
    std::vector<std::string> files_;
    cv::Size size_;
    double frameRate_ = 30.0;
};

// Natural order: runs of digits compare by value, the rest byte by byte; names equal that
// way ("f01", "f1") fall back to plain order so sorting is deterministic.
bool naturalLess(const std::string& a, const std::string& b);

// By extension, case-insensitive: png, jpg, jpeg, bmp, tif, tiff, ppm, pgm, pnm, webp.
bool isImageFileName(const std::string& name);

// Whether `path`'s file name holds a glob wildcard (* ? [).
bool hasGlobWildcard(const std::string& path);

}  // namespace omnitune
