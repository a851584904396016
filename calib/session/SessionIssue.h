#pragma once
// Errors and warnings about a recorded session are values: a kind plus where (file, line,
// key or column). The same type serves session.yml, truth.csv, the reader and the writer, so
// the GUI lists them all in one place.
#include <string>
#include <string_view>

namespace omnitune {

enum class SessionIssueKind {
    FileUnreadable,      // a file or folder cannot be opened or read
    ParseError,          // session.yml is not YAML; truth.csv's header is unusable
    NotASession,         // neither session.yml nor frames/, or YAML without `session_format`
    UnknownFormat,       // a session_format this build does not read
    MissingKey,          // warning: session.yml lacks a key, its default is used
    UnknownKey,          // warning: a key session.yml should not have (a typo?)
    WrongType,           // warning: a session.yml value of the wrong type, the default is used
    OutOfRange,          // warning: a session.yml number outside its range, the default is used
    MissingInfo,         // warning: session.yml is missing or unreadable; frames counted, settings unknown
    FrameCountMismatch,  // warning: session.yml's frame_count disagrees with frames/ (interrupted?)
    MissingFrames,       // warning: holes in frames/; reading those frames gives an error
    TruncatedFrame,      // warning: the last PNG is empty or cut short and was dropped
    MissingConfig,       // warning: session.yml names a config file that is not there
    BadNumber,           // truth.csv: a cell that should be a number is not; the row is skipped
    WrongColumnCount,    // truth.csv: a row with more or fewer cells than the header; skipped
    DuplicateFrame,      // truth.csv: a second row for a frame; the later row is skipped
    UnknownColumn,       // truth.csv: a header column this build does not know; ignored
    MissingColumn,       // truth.csv: the header lacks a column; its values are unknown
    BadValue,            // truth.csv: a number that is not allowed (ball_visible 2, ...); skipped
    FrameNotRecorded,    // truth.csv: a row for a frame the session does not hold; skipped
    FolderNotEmpty,      // the writer will not overwrite an existing session unless asked
    WrongFrame,          // the writer got a frame of the wrong size or type
    WriteError,          // writing a file failed
};

std::string_view sessionIssueKindName(SessionIssueKind k);

struct SessionIssue {
    SessionIssueKind kind = SessionIssueKind::ParseError;
    std::string file;     // as given by the caller (a path, or a name like "truth.csv")
    int line = 0;         // 1-based, 0 when unknown or not about a line
    std::string key;      // session.yml key path ("camera.gain") or truth.csv column; may be empty
    std::string message;  // what is wrong, in words

    // "truth.csv:7: px: \"12,5\" is not a number; row skipped"
    std::string toString() const;
};

}  // namespace omnitune
