#pragma once
// Errors and warnings about a file OmniTune reads or writes (config.yml, its mask, session.yml,
// truth.csv, frames) are values: a kind plus where (file, line, key). One type for every parser
// and writer, so tools print them alike and the GUI lists them in one place.
#include <string>

namespace omnitune {

enum class FileIssueKind {
    // any file
    FileUnreadable,      // a file or folder cannot be opened or read (missing, not a regular file, too large)
    ParseError,          // not YAML, nested too deep, or truncated; truth.csv's header is unusable
    MissingKey,          // warning: the key is absent, its default is used
    UnknownKey,          // warning: a key the format does not know (a typo?)
    DuplicateKey,        // a key or section written twice (YAML readers would keep one silently)
    WrongType,           // e.g. text where a number belongs (session.yml: a warning, the default is used)
    OutOfRange,          // a number outside the key's range (session.yml: a warning, the default is used)
    WriteError,          // writing a file failed
    // config.yml
    NotAConfig,          // YAML, but no OmniTune `schema` key
    UnknownSchema,       // a schema version this build does not read
    Inconsistent,        // keys that contradict each other (low above high, ...)
    MaskError,           // the mask image is missing, unreadable or of the wrong size
    OldForm,             // warning: keys of an older form, read as before (omnitune-config --upgrade rewrites them)
    // session.yml and the session folder
    NotASession,         // neither session.yml nor frames/, or YAML without `session_format`
    UnknownFormat,       // a session_format this build does not read
    MissingInfo,         // warning: session.yml is missing or unreadable; frames counted, settings unknown
    FrameCountMismatch,  // warning: session.yml's frame_count disagrees with frames/ (interrupted?)
    MissingFrames,       // warning: holes in frames/; reading those frames gives an error
    TruncatedFrame,      // warning: the last PNG is empty or cut short and was dropped
    MissingConfig,       // warning: session.yml names a config file that is not there
    FolderNotEmpty,      // the session writer will not overwrite an existing session unless asked
    WrongFrame,          // the session writer got a frame of the wrong size or type
    // truth.csv (each skips its row or column)
    BadNumber,           // a cell that should be a number is not
    WrongColumnCount,    // a row with more or fewer cells than the header
    DuplicateFrame,      // a second row for a frame; the later row is skipped
    UnknownColumn,       // a header column this build does not know; ignored
    MissingColumn,       // the header lacks a column; its values are unknown
    BadValue,            // a number that is not allowed (ball_visible 2, ...)
    FrameNotRecorded,    // a row for a frame the session does not hold
};

struct FileIssue {
    FileIssueKind kind = FileIssueKind::ParseError;
    std::string file;     // as given by the caller (a path, or a name like "truth.csv"); empty: in memory
    int line = 0;         // 1-based, 0 when unknown or not about a line
    std::string key;      // dotted key path ("hough.area_bounds") or truth.csv column; may be empty
    std::string message;  // what is wrong, in words

    // "config.yml:12: hough.canny_low: 900 is outside 0..1020" (no file part when in memory)
    std::string toString() const;
};

}  // namespace omnitune
