#include "calib/source/FrameSourceFactory.h"

#include "calib/source/ImageGlobSource.h"
#include "calib/session/Session.h"
#include "calib/source/SessionSource.h"
#include "calib/source/VideoSource.h"

#include <filesystem>

namespace omnitune {

namespace fs = std::filesystem;

namespace {

template <class Source>
SourceOpen<FrameSource> upcast(SourceOpen<Source>&& in)
{
    SourceOpen<FrameSource> out;
    out.source = std::move(in.source);
    out.error = std::move(in.error);
    out.warnings = std::move(in.warnings);
    return out;
}

SourceOpen<FrameSource> openSession(const std::string& folder)
{
    SourceOpen<FrameSource> out;
    SessionOpen opened = SessionReader::open(folder);
    if (!opened.ok()) {
        out.error = opened.error->toString();
        return out;
    }
    for (const SessionIssue& w : opened.reader->warnings()) out.warnings.push_back(w.toString());
    out.source = std::make_unique<SessionSource>(std::move(*opened.reader));
    return out;
}

bool holdsImages(const fs::path& dir)
{
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        if (isImageFileName(it->path().filename().string()) && it->is_regular_file(ec)) return true;
    return false;
}

}  // namespace

SourceOpen<FrameSource> openFrameSource(const std::string& path)
{
    const fs::path p(path);
    std::error_code ec;
    if (path.empty()) return upcast(SourceOpen<FrameSource>{nullptr, "no input given", {}});
    if (!fs::exists(p, ec)) {
        if (hasGlobWildcard(path)) return upcast(ImageGlobSource::open(path));
        return upcast(SourceOpen<FrameSource>{nullptr, path + ": no such file or folder", {}});
    }
    if (fs::is_directory(p, ec)) {
        if (fs::exists(p / kSessionInfoFile, ec) || fs::is_directory(p / kSessionFramesDir, ec)) return openSession(path);
        if (holdsImages(p)) return upcast(ImageGlobSource::open(path));
        return upcast(SourceOpen<FrameSource>{
            nullptr,
            path + ": the folder holds neither a recorded session (session.yml, frames/) nor image files (.png, .jpg, ...)",
            {}});
    }
    if (p.filename() == kSessionInfoFile) return openSession(p.parent_path().empty() ? "." : p.parent_path().string());
    if (isImageFileName(path)) return upcast(ImageGlobSource::open(path));
    auto video = VideoSource::open(path);
    if (!video.ok())
        video.error += "; expected a session folder, a video file, an image folder or a pattern like dir/*.png";
    return upcast(std::move(video));
}

}  // namespace omnitune
