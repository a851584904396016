#include "calib/source/ImageGlobSource.h"

#include "calib/source/ImageFile.h"

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fnmatch.h>

namespace omnitune {

namespace fs = std::filesystem;

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

bool ImageGlobSource::readsFile(const std::string& path) const
{
    return std::any_of(files_.begin(), files_.end(), [&](const std::string& f) { return sameFile(path, f); });
}

bool naturalLess(const std::string& a, const std::string& b)
{
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (isDigit(a[i]) && isDigit(b[j])) {
            std::size_t ie = i, je = j;
            while (ie < a.size() && isDigit(a[ie])) ++ie;
            while (je < b.size() && isDigit(b[je])) ++je;
            std::size_t iz = i, jz = j;  // skip leading zeros, then longer means larger
            while (iz + 1 < ie && a[iz] == '0') ++iz;
            while (jz + 1 < je && b[jz] == '0') ++jz;
            const std::string_view da(a.data() + iz, ie - iz), db(b.data() + jz, je - jz);
            if (da.size() != db.size()) return da.size() < db.size();
            if (da != db) return da < db;
            i = ie;
            j = je;
            continue;
        }
        if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
        ++i;
        ++j;
    }
    if ((i < a.size()) != (j < b.size())) return j < b.size();  // a prefix comes first
    return a < b;
}

bool isImageFileName(const std::string& name)
{
    std::string ext = fs::path(name).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* e : {".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff", ".ppm", ".pgm", ".pnm", ".webp"})
        if (ext == e) return true;
    return false;
}

bool hasGlobWildcard(const std::string& path)
{
    return fs::path(path).filename().string().find_first_of("*?[") != std::string::npos;
}

SourceOpen<ImageGlobSource> ImageGlobSource::open(const std::string& pattern, const ImageGlobOptions& options)
{
    CV_Assert(options.frameRate > 0.0);
    SourceOpen<ImageGlobSource> out;
    std::error_code ec;
    const fs::path p(pattern);
    fs::path dir;
    std::string namePattern = "*";
    if (fs::is_directory(p, ec)) {
        dir = p;
    } else if (fs::exists(p, ec)) {
        dir = p.parent_path();
        namePattern = p.filename().string();
    } else if (hasGlobWildcard(pattern)) {
        dir = p.parent_path();
        namePattern = p.filename().string();
        if (dir.string().find_first_of("*?[") != std::string::npos) {
            out.error = pattern + ": wildcards are allowed in the file name only, not in folders";
            return out;
        }
        if (dir.empty()) dir = ".";
        if (!fs::is_directory(dir, ec)) {
            out.error = pattern + ": no such folder " + dir.string();
            return out;
        }
    } else {
        out.error = pattern + ": no such file or folder";
        return out;
    }

    std::vector<fs::path> matches;
    if (fs::is_regular_file(p, ec)) {
        matches.push_back(p);
    } else {
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (!isImageFileName(name) || fnmatch(namePattern.c_str(), name.c_str(), FNM_PERIOD) != 0) continue;
            if (it->is_regular_file(ec)) matches.push_back(it->path());
        }
        if (ec) {
            out.error = dir.string() + ": cannot list the folder: " + ec.message();
            return out;
        }
    }
    if (matches.empty() || !isImageFileName(matches.front().filename().string())) {
        out.error = pattern + (fs::is_directory(p, ec) ? ": the folder holds no image files (.png, .jpg, ...)"
                                                       : ": matches no image file (.png, .jpg, ...)");
        return out;
    }
    std::sort(matches.begin(), matches.end(), [](const fs::path& a, const fs::path& b) {
        return naturalLess(a.filename().string(), b.filename().string());
    });

    std::unique_ptr<ImageGlobSource> s(new ImageGlobSource);
    s->pattern_ = pattern;
    s->frameRate_ = options.frameRate;
    for (const fs::path& m : matches) s->files_.push_back(m.string());
    for (const std::string& f : s->files_) {
        const cv::Mat first = readImageFile(f);
        if (first.empty()) {
            out.warnings.push_back(f + " does not decode as an image; reading it gives an error");
            continue;
        }
        s->size_ = first.size();
        break;
    }
    if (s->size_.empty()) {
        out.error = pattern + ": none of the " + std::to_string(s->files_.size()) + " files decodes as an image";
        out.warnings.clear();
        return out;
    }
    out.source = std::move(s);
    return out;
}

std::optional<FrameError> ImageGlobSource::readAt(int index, Frame& out)
{
    const std::string& path = files_[std::size_t(index)];
    std::error_code ec;
    if (!fs::exists(path, ec)) return FrameError{FrameErrorKind::Missing, index, path, path + " is missing"};
    cv::Mat image = readImageFile(path);
    if (image.empty())
        return FrameError{FrameErrorKind::Unreadable, index, path, path + " does not decode as an image"};
    if (image.size() != size_)
        return FrameError{FrameErrorKind::WrongSize, index, path,
                          path + " is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                              " but the first image is " + std::to_string(size_.width) + "x" +
                              std::to_string(size_.height)};
    out.image = image;
    out.format = PixelFormat::Bgr8;
    out.timestampS = index / frameRate_;
    out.camera.reset();
    return std::nullopt;
}

}  // namespace omnitune
