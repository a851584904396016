#pragma once
// Reading a recorded session folder (docs/sessions.md): frame-accurate random access to the
// PNG frames, the session info and the ground truth. Interrupted recordings open: when
// session.yml is missing or its frame_count disagrees with frames/, the frames on disk win
// and a warning says so; an empty or cut-short last PNG (a crash while writing it) is dropped.
#include "calib/source/FrameError.h"
#include "calib/session/Session.h"
#include "calib/session/SessionIssue.h"
#include "calib/session/TruthCsv.h"

#include <opencv2/core.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct SessionOpen;

class SessionReader {
public:
    // Opens `folder`. Fails (with the file and the fault) only when there is no session to
    // read: no such folder, neither session.yml nor frames/, or a session.yml that is not a
    // session or of an unknown session_format. Everything else is a warning.
    static SessionOpen open(const std::string& folder);

    const std::string& folder() const { return folder_; }
    // session.yml as read, with frameCount, width and height set to what frames/ holds.
    const SessionInfo& info() const { return info_; }
    // False when session.yml was missing or unreadable: info() is then defaults plus what the
    // frames tell, and the camera settings are unknown.
    bool hasInfoFile() const { return hasInfoFile_; }
    int frameCount() const { return info_.frameCount; }
    cv::Size frameSize() const { return {info_.width, info_.height}; }
    // s from the first frame: index / frame_rate.
    double timestampOf(int index) const;
    // Everything odd about the session (interrupted recording, bad truth rows, ...).
    const std::vector<SessionIssue>& warnings() const { return warnings_; }

    // <folder>/frames/000012.png
    std::string framePath(int index) const;
    // Decodes frame `index` (0..frameCount()-1) as BGR into `bgr`. A missing, undecodable or
    // wrongly sized frame is an error naming its file. Const and touching no shared state,
    // so threads may read frames in parallel.
    std::optional<FrameError> readFrame(int index, cv::Mat& bgr) const;

    // Ground truth by frame; empty when the session has no (usable) truth.csv.
    const std::map<int, TruthRow>& truth() const { return truth_; }
    // Whether truth.csv exists (truth() may still be empty: unreadable, or no usable row) and
    // how many data lines it holds; the warnings say what is wrong with the rest.
    bool hasTruthFile() const { return hasTruthFile_; }
    int truthRowsInFile() const { return truthRowsInFile_; }
    // The row for `frame`, or nullptr when that frame is not annotated.
    const TruthRow* truthFor(int frame) const;

    bool hasConfig() const { return !configPath_.empty(); }
    // The session's config file by the one rule of SessionConfig.h (session.yml's config_file
    // inside the folder, else config.yml when present); empty when none.
    const std::string& configPath() const { return configPath_; }
    // Why session.yml's config_file was not used; empty when it was, or named none.
    const std::optional<SessionIssue>& configIssue() const { return configIssue_; }

private:
    SessionReader() = default;

    std::string folder_;
    SessionInfo info_;
    bool hasInfoFile_ = false;
    std::vector<SessionIssue> warnings_;
    std::map<int, TruthRow> truth_;
    bool hasTruthFile_ = false;
    int truthRowsInFile_ = 0;
    std::string configPath_;
    std::optional<SessionIssue> configIssue_;
};

struct SessionOpen {
    std::optional<SessionReader> reader;  // set when ok()
    std::optional<SessionIssue> error;

    bool ok() const { return reader.has_value(); }
};

}  // namespace omnitune
