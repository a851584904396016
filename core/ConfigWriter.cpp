#include "core/ConfigWriter.h"

#include "core/ConfigSchema.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace omnitune {

namespace {

std::string comment(const ConfigKey& k)
{
    std::string c = " " + k.meaning;
    if (k.type == ValueType::Int || k.type == ValueType::Double || k.type == ValueType::DoubleList) {
        char range[96];
        std::snprintf(range, sizeof range, " [%g..%g%s%s]", k.min, k.max, k.unit.empty() ? "" : " ", k.unit.c_str());
        c += range;
    } else if (k.type == ValueType::Bool) {
        c += " [0/1]";
    }
    return c;
}

std::string errnoText() { return std::strerror(errno); }

}  // namespace

std::string serializeConfig(const Config& config)
{
    cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    fs.writeComment(" OmniTune detector configuration. Reference: docs/config.md");
    fs << "schema" << kConfigSchemaVersion;
    fs << "saved_by" << "OmniTune 0.1";
    std::vector<std::string> open;  // sections currently open
    for (const ConfigKey& k : configSchema()) {
        auto parts = splitConfigPath(k.path);
        const std::string leaf = parts.back();
        parts.pop_back();
        std::size_t common = 0;
        while (common < open.size() && common < parts.size() && open[common] == parts[common]) ++common;
        while (open.size() > common) {
            fs << "}";
            open.pop_back();
        }
        while (open.size() < parts.size()) {
            fs << parts[open.size()] << "{";
            open.push_back(parts[open.size()]);
        }
        fs.writeComment(comment(k));
        const ConfigValue v = k.get(config);
        // Text goes through write(), not <<, which takes a text starting with [ { ] } for the
        // start or end of a list or map (a model "[test]" wrote a broken file, "]x" threw).
        if (const std::string* s = std::get_if<std::string>(&v)) {
            fs.write(leaf, *s);
            continue;
        }
        fs << leaf;
        if (const int* i = std::get_if<int>(&v)) fs << *i;
        else if (const double* d = std::get_if<double>(&v)) fs << *d;
        else if (const bool* b = std::get_if<bool>(&v)) fs << int(*b);
        else fs << std::get<std::vector<double>>(v);
    }
    while (!open.empty()) {
        fs << "}";
        open.pop_back();
    }
    fs.writeComment(" end marker: a saved file without it was cut short");
    fs << "complete" << 1;
    return fs.releaseAndGetString();
}

namespace {

// Step 1 of an atomic write: the bytes in `path`.tmp, flushed to disk.
std::optional<std::string> writeTemp(const std::string& path, const std::string& bytes)
{
    const std::string tmp = path + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return "cannot create " + tmp + ": " + errnoText();
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const std::string why = errnoText();
            ::close(fd);
            ::unlink(tmp.c_str());
            return "cannot write " + tmp + ": " + why;
        }
        done += std::size_t(n);
    }
    const bool synced = ::fsync(fd) == 0;
    const std::string syncError = synced ? std::string() : errnoText();
    const bool closed = ::close(fd) == 0;  // always closed, whether the flush worked or not
    if (!synced || !closed) {
        const std::string why = synced ? errnoText() : syncError;
        ::unlink(tmp.c_str());
        return "cannot flush " + tmp + ": " + why;
    }
    return std::nullopt;
}

// Step 2: keep `path`.bak when asked, then rename the temp over `path`.
std::optional<std::string> replaceWithTemp(const std::string& path, bool keepBackup)
{
    namespace fs = std::filesystem;
    const std::string tmp = path + ".tmp";
    std::error_code ec;
    if (keepBackup && fs::exists(path, ec)) {
        fs::copy_file(path, path + ".bak", fs::copy_options::overwrite_existing, ec);
        if (ec) {
            ::unlink(tmp.c_str());
            return "cannot keep the backup " + path + ".bak: " + ec.message();
        }
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = errnoText();
        ::unlink(tmp.c_str());
        return "cannot replace " + path + ": " + why;
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes, bool keepBackup)
{
    if (auto err = writeTemp(path, bytes)) return err;
    return replaceWithTemp(path, keepBackup);
}

std::optional<ConfigIssue> saveConfig(const Config& config, const std::string& path, bool keepBackup)
{
    const auto problems = checkConfig(config, path);
    if (!problems.empty()) return problems.front();
    // Both files are written and flushed before either replaces its old version, so a failure
    // (full disk, no permission) never leaves a new mask beside the old config.
    std::string maskPath;
    if (!config.mask.empty()) {
        if (config.geometry.maskFile.empty())
            return ConfigIssue{ConfigIssueKind::MaskError, path, 0, "geometry.mask_file",
                               "the config holds a mask image but geometry.mask_file names no file for it"};
        maskPath = (std::filesystem::path(path).parent_path() / config.geometry.maskFile).string();
        std::vector<std::uint8_t> png;
        if (!cv::imencode(".png", config.mask, png))
            return ConfigIssue{ConfigIssueKind::WriteError, maskPath, 0, "geometry.mask_file", "cannot encode the mask as PNG"};
        if (auto err = writeTemp(maskPath, std::string(png.begin(), png.end())))
            return ConfigIssue{ConfigIssueKind::WriteError, maskPath, 0, "geometry.mask_file", *err};
    }
    if (auto err = writeTemp(path, serializeConfig(config))) {
        if (!maskPath.empty()) ::unlink((maskPath + ".tmp").c_str());
        return ConfigIssue{ConfigIssueKind::WriteError, path, 0, "", *err};
    }
    if (!maskPath.empty()) {
        if (auto err = replaceWithTemp(maskPath, keepBackup)) {
            ::unlink((path + ".tmp").c_str());
            return ConfigIssue{ConfigIssueKind::WriteError, maskPath, 0, "geometry.mask_file", *err};
        }
    }
    if (auto err = replaceWithTemp(path, keepBackup)) return ConfigIssue{ConfigIssueKind::WriteError, path, 0, "", *err};
    return std::nullopt;
}

}  // namespace omnitune
