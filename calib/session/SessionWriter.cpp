#include "calib/session/SessionWriter.h"

#include "core/ConfigWriter.h"

#include <opencv2/imgcodecs.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

namespace omnitune {

namespace fs = std::filesystem;

namespace {

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// The files a session consists of, with the .bak/.tmp that atomic writes may leave.
void removeSession(const fs::path& dir, std::error_code& ec)
{
    for (std::string_view name : {kSessionInfoFile, kSessionTruthFile, kSessionConfigFile}) {
        const std::string base(name);
        for (const char* suffix : {"", ".bak", ".tmp"}) {
            fs::remove(dir / (base + suffix), ec);
            if (ec) return;
        }
    }
    fs::remove_all(dir / kSessionFramesDir, ec);
}

}  // namespace

SessionCreate SessionWriter::create(const std::string& folder, const SessionInfo& info,
                                    const SessionWriterOptions& options)
{
    CV_Assert(options.infoEveryFrames >= 1);
    CV_Assert(options.pngCompression >= 0 && options.pngCompression <= 9);
    SessionCreate out;
    auto fail = [&](SessionIssueKind kind, const std::string& message) {
        out.error = SessionIssue{kind, folder, 0, "", message};
        return std::move(out);
    };
    // The info is checked by the parser that will read it back, so a session is never
    // written that reads with warnings (a gain of 5000, a frame rate of 0).
    const SessionInfoParse check = parseSessionInfo(serializeSessionInfo(info), std::string(kSessionInfoFile));
    if (!check.warnings.empty()) {
        const SessionIssue& w = check.warnings.front();
        const std::string why = w.message.substr(0, w.message.find(", the default"));
        out.error = SessionIssue{w.kind, folder, 0, w.key, "cannot record " + w.key + ": " + why};
        return out;
    }
    const fs::path dir(folder);
    std::error_code ec;
    if (fs::exists(dir, ec)) {
        if (!fs::is_directory(dir, ec)) return fail(SessionIssueKind::WriteError, "is a file, not a folder");
        if (!fs::is_empty(dir, ec)) {
            const bool isSession = fs::exists(dir / kSessionInfoFile, ec) || fs::is_directory(dir / kSessionFramesDir, ec);
            if (!isSession)
                return fail(SessionIssueKind::FolderNotEmpty,
                            "is not empty and holds no session; choose an empty or new folder");
            if (!options.overwrite)
                return fail(SessionIssueKind::FolderNotEmpty,
                            "already holds a session; choose another folder or allow overwriting it");
            removeSession(dir, ec);
            if (ec) return fail(SessionIssueKind::WriteError, "cannot remove the old session: " + ec.message());
        }
    }
    fs::create_directories(dir / kSessionFramesDir, ec);
    if (ec) return fail(SessionIssueKind::WriteError, "cannot create " + (dir / kSessionFramesDir).string() + ": " + ec.message());

    SessionWriter w;
    w.folder_ = folder;
    w.info_ = info;
    w.info_.frameCount = 0;
    if (w.info_.created.empty()) w.info_.created = isoUtcNow();
    w.info_.complete = false;  // until finish(): a session killed mid-recording says so
    w.options_ = options;
    w.finished_ = false;
    if (auto err = w.writeInfo()) {
        w.finished_ = true;
        out.error = err;
        return out;
    }
    out.writer.emplace(std::move(w));
    return out;
}

SessionWriter::SessionWriter(SessionWriter&& other) noexcept
    : folder_(std::move(other.folder_)),
      info_(std::move(other.info_)),
      options_(other.options_),
      truth_(std::move(other.truth_)),
      finished_(std::exchange(other.finished_, true))
{
}

SessionWriter& SessionWriter::operator=(SessionWriter&& other) noexcept
{
    if (this != &other) {
        try {
            finish();
        } catch (...) {  // a destructor-like path: nobody to report to
        }
        folder_ = std::move(other.folder_);
        info_ = std::move(other.info_);
        options_ = other.options_;
        truth_ = std::move(other.truth_);
        finished_ = std::exchange(other.finished_, true);
    }
    return *this;
}

SessionWriter::~SessionWriter()
{
    try {
        finish();
    } catch (...) {  // never throw from a destructor; finish() reports errors to those who call it
    }
}

std::optional<SessionIssue> SessionWriter::writeInfo()
{
    const std::string path = (fs::path(folder_) / kSessionInfoFile).string();
    if (auto err = writeFileAtomically(path, serializeSessionInfo(info_), false))
        return SessionIssue{SessionIssueKind::WriteError, path, 0, "", *err};
    return std::nullopt;
}

std::optional<SessionIssue> SessionWriter::appendFrame(const cv::Mat& bgr, const std::optional<TruthRow>& truth)
{
    const int index = info_.frameCount;
    const std::string name = (fs::path(kSessionFramesDir) / sessionFrameName(index)).string();
    auto refuse = [&](SessionIssueKind kind, const std::string& message) {
        return SessionIssue{kind, (fs::path(folder_) / name).string(), 0, "", message};
    };
    if (finished_) return refuse(SessionIssueKind::WriteError, "the session is finished; no more frames can be added");
    if (index >= kSessionMaxFrames)
        return refuse(SessionIssueKind::WriteError, "the session is full (" + std::to_string(kSessionMaxFrames) +
                                                        " frames); start another one");
    if (bgr.empty() || bgr.type() != CV_8UC3)
        return refuse(SessionIssueKind::WrongFrame,
                      "frame " + std::to_string(index) + " refused: expected an 8-bit BGR image (CV_8UC3), got " +
                          (bgr.empty() ? std::string("an empty image") : cv::typeToString(bgr.type())));
    const bool firstSetsSize = info_.width <= 0 || info_.height <= 0;
    if (!firstSetsSize && (bgr.cols != info_.width || bgr.rows != info_.height))
        return refuse(SessionIssueKind::WrongFrame,
                      "frame " + std::to_string(index) + " refused: it is " + sizeText(bgr.cols, bgr.rows) +
                          " but the session's frames are " + sizeText(info_.width, info_.height));

    std::vector<std::uint8_t> png;
    try {
        if (!cv::imencode(".png", bgr, png, {cv::IMWRITE_PNG_COMPRESSION, options_.pngCompression}))
            return refuse(SessionIssueKind::WriteError, "cannot encode frame " + std::to_string(index) + " as PNG");
    } catch (const cv::Exception& e) {
        return refuse(SessionIssueKind::WriteError, "cannot encode frame " + std::to_string(index) + " as PNG: " + e.err);
    }
    const std::string path = (fs::path(folder_) / name).string();
    if (auto err = writeFileAtomically(path, std::string(png.begin(), png.end()), false))
        return refuse(SessionIssueKind::WriteError, *err);

    ++info_.frameCount;
    std::optional<SessionIssue> problem;
    if (firstSetsSize) {
        info_.width = bgr.cols;
        info_.height = bgr.rows;
    }
    if (truth) {
        const std::string truthPath = (fs::path(folder_) / kSessionTruthFile).string();
        if (!truth_.is_open()) {
            std::error_code ec;
            const bool fresh = !fs::exists(truthPath, ec) || fs::file_size(truthPath, ec) == 0;
            truth_.open(truthPath, std::ios::binary | std::ios::app);
            if (truth_ && fresh) truth_ << truthCsvHeader() << '\n';
        }
        TruthRow row = *truth;
        row.frame = index;
        // Flushed per row so a crash keeps every row whose frame is on disk.
        errno = 0;
        truth_ << formatTruthRow(row) << '\n' << std::flush;
        if (!truth_)
            problem = SessionIssue{SessionIssueKind::WriteError, truthPath, 0, "",
                                   "frame " + std::to_string(index) + " was saved but its truth row could not be written" +
                                       (errno ? std::string(": ") + std::strerror(errno) : std::string())};
    }
    if (firstSetsSize || info_.frameCount % options_.infoEveryFrames == 0)
        if (auto err = writeInfo(); err && !problem) problem = err;
    return problem;
}

std::optional<SessionIssue> SessionWriter::writeConfig(const Config& config)
{
    if (finished_) return SessionIssue{SessionIssueKind::WriteError, folder_, 0, "", "the session is finished"};
    const std::string path = (fs::path(folder_) / kSessionConfigFile).string();
    if (auto issue = saveConfig(config, path))
        return SessionIssue{SessionIssueKind::WriteError, path, issue->line, issue->key, issue->message};
    info_.configFile = std::string(kSessionConfigFile);
    return writeInfo();
}

std::optional<SessionIssue> SessionWriter::finish()
{
    if (finished_) return std::nullopt;
    finished_ = true;
    info_.complete = true;
    std::optional<SessionIssue> problem = writeInfo();
    if (truth_.is_open()) {
        truth_.close();
        if (truth_.fail() && !problem)
            problem = SessionIssue{SessionIssueKind::WriteError, (fs::path(folder_) / kSessionTruthFile).string(), 0, "",
                                   "cannot close"};
    }
    return problem;
}

}  // namespace omnitune
