#pragma once
// "Save as session" (issue 11): an image folder, glob or video becomes a session folder
// (docs/sessions.md) so that it can be marked with ground truth and evaluated. Every frame the
// source gives is written losslessly as frames/NNNNNN.png, the config in use as config.yml
// (with its mask), and an empty truth.csv (the header only) waits for the marks.
#include "calib/session/SessionIssue.h"
#include "calib/session/SessionWriter.h"
#include "calib/source/FrameSource.h"

#include "core/Config.h"
#include "core/Progress.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct SessionExportOptions {
    SessionWriterOptions writer;  // overwrite an existing session, PNG compression
    std::string notes;            // session.yml's notes; empty: "saved from <source>"
};

struct SessionExportResult {
    int frames = 0;                     // frames written
    std::vector<std::string> skipped;   // one line per source frame that could not be read (left out)
    bool cancelled = false;             // stopped by `progress`; the session holds the frames written so far
    std::string configNote;             // why config.yml was not written (a config for another frame size); empty: written
    std::optional<SessionIssue> error;  // the file and the fault; nothing usable was made

    bool ok() const { return !error.has_value(); }
};

// Reads `source` from its first frame to its end (kNext, so a video without a frame count
// works too) and writes the session to `folder`. `config` is saved as the session's config.yml
// when its geometry is for the frames' size (else `configNote` says why not).
// `progress` (may be null) sees the share of frames read when the source knows its length and
// may cancel between frames. A source with no readable frame is an error.
SessionExportResult exportSession(FrameSource& source, const std::string& folder, const Config& config,
                                  const SessionExportOptions& options = {}, Progress* progress = nullptr);

}  // namespace omnitune
