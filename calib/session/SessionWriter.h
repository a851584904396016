#pragma once
// Recording a session folder (docs/sessions.md). Each frame is written as
// frames/NNNNNN.png through a temporary file, flushed and renamed, and session.yml is
// rewritten (atomically) every few frames, so a crash or a pulled battery loses at most the
// frame being written; SessionReader opens whatever is left. session.yml says `complete:
// false` until finish() (or the destructor) closes the session, so a recording killed right
// after a rewrite is still known to be interrupted.
#include "calib/session/Session.h"
#include "calib/session/SessionIssue.h"
#include "calib/session/TruthCsv.h"

#include "core/Config.h"

#include <opencv2/core.hpp>

#include <fstream>
#include <optional>
#include <string>

namespace omnitune {

struct SessionWriterOptions {
    // Replace an existing session in the folder: removes its session.yml, frames/, truth.csv
    // and config.yml (other files stay). A non-empty folder that holds no session is never
    // emptied, whatever this says.
    bool overwrite = false;
    // Rewrite session.yml after every this many frames, >= 1. Larger saves a little disk
    // traffic; the reader recounts the frames anyway when it is stale.
    int infoEveryFrames = 30;
    // zlib level of the PNGs, 0..9. Lossless at every level: higher is smaller and slower
    // (1 keeps up with 30 frames/s of 640x480 on a robot's CPU).
    int pngCompression = 1;
};

struct SessionCreate;

class SessionWriter {
public:
    // Creates `folder` (and its parents) and writes session.yml with no frames. `info`'s
    // width and height may be 0: the first frame sets them. `info.created` is filled with
    // the current time when empty; frameCount is ignored. Settings outside their ranges
    // (docs/sessions.md) are refused before anything is written.
    static SessionCreate create(const std::string& folder, const SessionInfo& info,
                                const SessionWriterOptions& options = {});

    SessionWriter(SessionWriter&& other) noexcept;
    SessionWriter& operator=(SessionWriter&& other) noexcept;
    SessionWriter(const SessionWriter&) = delete;
    SessionWriter& operator=(const SessionWriter&) = delete;
    // Finishes when finish() was not called; call finish() yourself to see its errors.
    ~SessionWriter();

    // Writes `bgr` (CV_8UC3, the session's size) as the next frame and, when given, its
    // ground truth as a truth.csv row (the row's `frame` is set to the new frame's index).
    // A frame of another size or type is refused with a message and nothing is written.
    std::optional<SessionIssue> appendFrame(const cv::Mat& bgr, const std::optional<TruthRow>& truth = std::nullopt);

    // Saves `config` (and its mask) as config.yml in the session and names it in session.yml.
    std::optional<SessionIssue> writeConfig(const Config& config);

    // Writes the final session.yml (complete: true) and closes truth.csv. Later appends are refused.
    std::optional<SessionIssue> finish();

    const std::string& folder() const { return folder_; }
    const SessionInfo& info() const { return info_; }
    int frameCount() const { return info_.frameCount; }
    bool isFinished() const { return finished_; }

private:
    SessionWriter() = default;
    std::optional<SessionIssue> writeInfo();

    std::string folder_;
    SessionInfo info_;
    SessionWriterOptions options_;
    std::ofstream truth_;  // opened at the first truth row
    bool finished_ = true;  // a moved-from or default writer has nothing to finish
};

struct SessionCreate {
    std::optional<SessionWriter> writer;  // set when ok()
    std::optional<SessionIssue> error;

    bool ok() const { return writer.has_value(); }
};

}  // namespace omnitune
