#include "calib/session/SessionReader.h"

#include "calib/session/SessionConfig.h"
#include "calib/source/ImageFile.h"
#include "core/RegularFile.h"

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
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

// What frames/ holds: the frame numbers named exactly as sessionFrameName() makes them, and
// the names numbered past kSessionMaxFrames (refused, never counted).
struct FramesOnDisk {
    std::set<int> present;
    std::vector<std::string> pastLimit;
};

FramesOnDisk framesOnDisk(const fs::path& framesDir)
{
    FramesOnDisk out;
    std::error_code ec;
    for (fs::directory_iterator it(framesDir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() < 10 || name.compare(name.size() - 4, 4, ".png") != 0) continue;
        const std::string digits = name.substr(0, name.size() - 4);
        if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
        if (digits.size() > 6) {  // "1000000.png", "999999999.png": past the six-digit names
            if (digits[0] != '0') out.pastLimit.push_back(name);
            continue;
        }
        const int index = std::stoi(digits);
        if (sessionFrameName(index) == name) out.present.insert(index);
    }
    std::sort(out.pastLimit.begin(), out.pastLimit.end());
    return out;
}

// The frames that belong to the session: every frame below session.yml's frame_count, then
// the run that continues them without a gap (the recorder writes in order, so what an
// interruption leaves past a stale frame_count is such a run). Anything further is a stray
// file; counting it would make one "frames/999999999.png" a billion-frame session.
std::set<int> sessionFrames(const std::set<int>& present, int frameCountInInfo, std::vector<int>& strays)
{
    std::set<int> kept(present.begin(), present.lower_bound(frameCountInInfo));
    int next = std::max(frameCountInInfo, 0);
    if (!kept.empty()) next = std::max(next, *kept.rbegin() + 1);
    for (auto it = present.lower_bound(next); it != present.end(); ++it) {
        if (*it == next) {
            kept.insert(next++);
            continue;
        }
        strays.push_back(*it);
    }
    return kept;
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

std::string nameList(const std::vector<std::string>& names, std::size_t shown)
{
    std::string s;
    for (std::size_t i = 0; i < names.size() && i < shown; ++i) s += (s.empty() ? "" : ", ") + names[i];
    if (names.size() > shown) s += " and " + std::to_string(names.size() - shown) + " more";
    return s;
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

    const FramesOnDisk disk = haveFrames ? framesOnDisk(framesDir) : FramesOnDisk{};
    if (!disk.pastLimit.empty())
        r.warnings_.push_back({SessionIssueKind::FrameCountMismatch, framesDir.string(), 0, "",
                               nameList(disk.pastLimit, 5) + (disk.pastLimit.size() == 1 ? " is" : " are") +
                                   " numbered past the limit of " + std::to_string(kSessionMaxFrames) +
                                   " frames (000000.png..999999.png); ignored"});
    std::vector<int> strays;
    std::set<int> present = sessionFrames(disk.present, r.hasInfoFile_ ? r.info_.frameCount : 0, strays);
    if (!strays.empty())
        r.warnings_.push_back({SessionIssueKind::FrameCountMismatch, framesDir.string(), 0, "",
                               frameList({strays.begin(), strays.begin() + std::min<std::size_t>(strays.size(), 5)},
                                         strays.size()) +
                                   (strays.size() == 1 ? " lies" : " lie") + " past the session's " +
                                   std::to_string(present.empty() ? 0 : *present.rbegin() + 1) +
                                   " frames without continuing them (a stray file?); ignored"});
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
    if (r.hasInfoFile_ && r.info_.complete == false)
        r.warnings_.push_back({SessionIssueKind::FrameCountMismatch, infoPath.string(), 0, "complete",
                               "the recording was not closed (complete: false): it was interrupted, frames/ holds " +
                                   std::to_string(onDisk) + " frames and the last moments may be missing"});
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
        r.hasTruthFile_ = true;
        const auto text = readText(truthPath);
        if (!text) {
            r.warnings_.push_back({SessionIssueKind::FileUnreadable, truthPath.string(), 0, "",
                                   "cannot be read; the session has no ground truth"});
        } else {
            // Values outside the frames are refused here, before anything draws or averages them.
            TruthParse parsed = parseTruthCsv(*text, truthPath.string(), TruthLimits{{r.info_.width, r.info_.height}});
            r.truthRowsInFile_ = parsed.dataRows;
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

    SessionConfigChoice config = sessionConfigPath(folder, r.info_.configFile, infoPath.string());
    r.configPath_ = config.path;
    if (config.issue) r.warnings_.push_back(*config.issue);
    r.configIssue_ = config.issue;

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
