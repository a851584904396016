#pragma once
// A recorded session is a folder (layout in docs/sessions.md):
//   session.yml        SessionInfo, written with cv::FileStorage
//   frames/000000.png  lossless BGR frames, numbered from 0 with six digits
//   truth.csv          optional ground truth per frame (TruthCsv.h)
//   config.yml         optional detector config the session was tuned with
// This header holds SessionInfo and the pure session.yml parser and serializer: text in,
// struct plus typed warnings out, so the reader, the GUI and the tests share one reading.
#include "calib/session/SessionIssue.h"

#include "core/CameraSettings.h"
#include "core/PixelFormat.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace omnitune {

inline constexpr int kSessionFormatVersion = 1;
inline constexpr std::string_view kSessionInfoFile = "session.yml";
inline constexpr std::string_view kSessionFramesDir = "frames";
inline constexpr std::string_view kSessionTruthFile = "truth.csv";
inline constexpr std::string_view kSessionConfigFile = "config.yml";
inline constexpr int kSessionMaxFrames = 1000000;  // six-digit frame names: 000000..999999
// px: the largest frame side a session may state (frame_width, frame_height); truth.csv values
// of a session whose size is unknown are checked against it.
inline constexpr int kSessionMaxFrameSide = 100000;

struct SessionInfo {
    CameraSettings camera;                        // the camera as set while recording
    int width = 0;                                // px of every frame; 0 = unknown (take it from frame 0)
    int height = 0;                               // px; 0 = unknown
    PixelFormat pixelFormat = PixelFormat::Bgr8;  // what the camera delivered; frames on disk are BGR PNG
    int frameCount = 0;                           // frames/000000.png .. frameCount-1
    double frameRate = 30.0;                      // frames/s of the recording; frame i is at i / frameRate s
    std::string notes;                            // free text, may span lines
    std::string created;                          // ISO 8601 UTC, "2024-05-01T14:03:00Z"
    std::string configFile;                       // "config.yml" when the session carries one; empty otherwise
    // true: the recorder closed the session (SessionWriter::finish); false: written while
    // recording, so a session still saying false was interrupted; empty: the file does not
    // say (written by hand or by an older build).
    std::optional<bool> complete;
};

struct SessionInfoParse {
    SessionInfo info;                    // meaningful only when ok()
    std::vector<SessionIssue> warnings;  // missing, unknown, mistyped or out-of-range keys (defaults used)
    std::optional<SessionIssue> error;   // not YAML, not a session, or an unknown session_format

    bool ok() const { return !error.has_value(); }
};

// `fileName` only labels the messages.
SessionInfoParse parseSessionInfo(const std::string& text, const std::string& fileName);

// session.yml text; parseSessionInfo(serializeSessionInfo(i)) gives back `i`.
std::string serializeSessionInfo(const SessionInfo& info);

// "000012.png": the name of frame `index` inside frames/.
std::string sessionFrameName(int index);

// The current time as ISO 8601 UTC to the second, for SessionInfo::created.
std::string isoUtcNow();

}  // namespace omnitune
