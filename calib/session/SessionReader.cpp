#include "calib/session/SessionReader.h"

#include "calib/source/ImageFile.h"
#include "core/RegularFile.h"

#include <opencv2/imgcodecs.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace omnitune {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> readText(const fs::path& path)
{
    if (checkRegularFile(path.string())) return std::nullopt;  // a FIFO would block the reader for good
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return buffer.str();
}

// The frame numbers present in frames/: names exactly as sessionFrameName() makes them.
std::set<int> framesOnDisk(const fs::path& framesDir)
{
    std::set<int> present;
    std::error_code ec;
    for (fs::directory_iterator it(framesDir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() < 10 || name.compare(name.size() - 4, 4, ".png") != 0) continue;
        const std::string digits = name.substr(0, name.size() - 4);
        if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
        const int index = std::stoi(digits);
        if (sessionFrameName(index) == name) present.insert(index);
    }
    return present;
}

// A PNG written to the end starts with the signature and ends with the IEND chunk; a crash
// mid-write leaves a file without the end. Cheaper than decoding.
bool isCompletePng(const fs::path& path)
{
    static const std::array<unsigned char, 8> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const std::array<unsigned char, 12> iend = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::array<unsigned char, 8> head{};
    std::array<unsigned char, 12> tail{};
    if (!in.read(reinterpret_cast<char*>(head.data()), head.size()) || head != signature) return false;
    in.seekg(-std::streamoff(tail.size()), std::ios::end);
    return in.read(reinterpret_cast<char*>(tail.data()), tail.size()) && tail == iend;
}

std::string frameList(const std::vector<int>& indices, std::size_t total)
{
    std::string s;
    for (int i : indices) s += (s.empty() ? "" : ", ") + sessionFrameName(i);
    if (total > indices.size()) s += " and " + std::to_string(total - indices.size()) + " more";
    return s;
}

}  // namespace

SessionOpen SessionReader::open(const std::string& folder)
{
    SessionOpen out;
    auto fail = [&](SessionIssueKind kind, const std::string& file, const std::string& message) {
        out.error = SessionIssue{kind, file, 0, "", message};
        return out;
    };
    const fs::path dir(folder);
    std::error_code ec;
    if (!fs::exists(dir, ec)) return fail(SessionIssueKind::FileUnreadable, folder, "no such folder");
    if (!fs::is_directory(dir, ec))
        return fail(SessionIssueKind::NotASession, folder, "is a file; a session is a folder holding session.yml and frames/");
    const fs::path infoPath = dir / kSessionInfoFile;
    const fs::path framesDir = dir / kSessionFramesDir;
    const bool haveInfo = fs::exists(infoPath, ec);
    const bool haveFrames = fs::is_directory(framesDir, ec);
    if (!haveInfo && !haveFrames)
        return fail(SessionIssueKind::NotASession, folder,
                    "neither session.yml nor frames/ is there: this folder is not a recorded session");

    SessionReader r;
    r.folder_ = folder;
    if (haveInfo) {
        const auto text = readText(infoPath);
        if (!text) return fail(SessionIssueKind::FileUnreadable, infoPath.string(), "cannot be read");
        SessionInfoParse parsed = parseSessionInfo(*text, infoPath.string());
        if (parsed.ok()) {
            r.info_ = parsed.info;
            r.hasInfoFile_ = true;
            r.warnings_ = parsed.warnings;
        } else if (parsed.error->kind == SessionIssueKind::ParseError && haveFrames) {
            // Garbled (a disk fault; the writer replaces it atomically): the frames still play.
            SessionIssue w = *parsed.error;
            w.message += "; ignoring it and counting the frames instead";
            r.warnings_.push_back(w);
        } else {
            out.error = parsed.error;  // not a session, or a format we must not guess at
            return out;
        }
    }

    std::set<int> present = haveFrames ? framesOnDisk(framesDir) : std::set<int>{};
    if (!present.empty()) {
        const int last = *present.rbegin();
        const fs::path lastPath = framesDir / sessionFrameName(last);
        const auto bytes = fs::file_size(lastPath, ec);
        if (ec || bytes == 0 || !isCompletePng(lastPath)) {
            r.warnings_.push_back({SessionIssueKind::TruncatedFrame, lastPath.string(), 0, "",
                                   std::string(ec || bytes == 0 ? "is empty" : "is not a complete PNG") +
                                       " (the recording stopped while writing it); dropped"});
            present.erase(last);
        }
    }
    const int onDisk = present.empty() ? 0 : *present.rbegin() + 1;
    if (!r.hasInfoFile_ && !haveInfo)
        r.warnings_.push_back({SessionIssueKind::MissingInfo, infoPath.string(), 0, "",
                               "missing (the recording was interrupted before writing it?): counted " +
                                   std::to_string(onDisk) + " frames in frames/; camera settings unknown"});
    else if (r.hasInfoFile_ && r.info_.frameCount != onDisk)
        r.warnings_.push_back({SessionIssueKind::FrameCountMismatch, infoPath.string(), 0, "frame_count",
                               "says " + std::to_string(r.info_.frameCount) + " frames but frames/ holds " +
                                   std::to_string(onDisk) + " (an interrupted recording?); using " +
                                   std::to_string(onDisk)});
    r.info_.frameCount = onDisk;
    if (std::size_t(onDisk) > present.size()) {
        std::vector<int> holes;
        for (int i = 0; i < onDisk && holes.size() < 5; ++i)
            if (!present.count(i)) holes.push_back(i);
        r.warnings_.push_back({SessionIssueKind::MissingFrames, framesDir.string(), 0, "",
                               "lacks " + frameList(holes, std::size_t(onDisk) - present.size()) +
                                   "; reading those frames gives an error"});
    }

    // Size unknown (no or incomplete session.yml): the first frame that decodes tells.
    if (r.info_.width <= 0 || r.info_.height <= 0) {
        r.info_.width = r.info_.height = 0;
        for (int i : present) {
            const cv::Mat first = readImageFile(r.framePath(i));
            if (first.empty()) continue;
            r.info_.width = first.cols;
            r.info_.height = first.rows;
            break;
        }
    }

    const fs::path truthPath = dir / kSessionTruthFile;
    if (fs::exists(truthPath, ec)) {
        const auto text = readText(truthPath);
        if (!text) {
            r.warnings_.push_back({SessionIssueKind::FileUnreadable, truthPath.string(), 0, "",
                                   "cannot be read; the session has no ground truth"});
        } else {
            TruthParse parsed = parseTruthCsv(*text, truthPath.string());
            r.warnings_.insert(r.warnings_.end(), parsed.warnings.begin(), parsed.warnings.end());
            if (!parsed.ok()) {
                SessionIssue w = *parsed.error;
                w.message += "; the session has no ground truth";
                r.warnings_.push_back(w);
            }
            for (auto& [frame, row] : parsed.rows) {
                if (frame >= onDisk) {
                    r.warnings_.push_back({SessionIssueKind::FrameNotRecorded, truthPath.string(), 0, "frame",
                                           "a row for frame " + std::to_string(frame) + ", but the session holds " +
                                               std::to_string(onDisk) + " frames; row ignored"});
                    continue;
                }
                r.truth_.emplace(frame, row);
            }
        }
    }

    if (!r.info_.configFile.empty()) {
        const fs::path config = dir / r.info_.configFile;
        if (fs::exists(config, ec))
            r.configPath_ = config.string();
        else
            r.warnings_.push_back({SessionIssueKind::MissingConfig, infoPath.string(), 0, "config_file",
                                   "names " + r.info_.configFile + ", which is not in the session folder"});
    } else if (fs::exists(dir / kSessionConfigFile, ec)) {
        r.configPath_ = (dir / kSessionConfigFile).string();
    }

    out.reader.emplace(std::move(r));
    return out;
}

double SessionReader::timestampOf(int index) const
{
    return info_.frameRate > 0.0 ? index / info_.frameRate : 0.0;
}

std::string SessionReader::framePath(int index) const
{
    return (fs::path(folder_) / kSessionFramesDir / sessionFrameName(index)).string();
}

std::optional<FrameError> SessionReader::readFrame(int index, cv::Mat& bgr) const
{
    if (index < 0 || index >= frameCount())
        return FrameError{FrameErrorKind::OutOfRange, index, "",
                          "session " + folder_ + " has no frame " + std::to_string(index) + " (it holds " +
                              std::to_string(frameCount()) + ")"};
    const std::string path = framePath(index);
    std::error_code ec;
    if (!fs::exists(path, ec))
        return FrameError{FrameErrorKind::Missing, index, path, path + " is missing"};
    cv::Mat image = readImageFile(path);
    if (image.empty())
        return FrameError{FrameErrorKind::Unreadable, index, path, path + " does not decode as an image"};
    if (image.cols != info_.width || image.rows != info_.height)
        return FrameError{FrameErrorKind::WrongSize, index, path,
                          path + " is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                              " but the session's frames are " + std::to_string(info_.width) + "x" +
                              std::to_string(info_.height)};
    bgr = image;
    return std::nullopt;
}

const TruthRow* SessionReader::truthFor(int frame) const
{
    const auto it = truth_.find(frame);
    return it == truth_.end() ? nullptr : &it->second;
}

}  // namespace omnitune
