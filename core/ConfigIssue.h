#pragma once
// Errors and warnings about a config file are values: a kind plus where (file, line, key).
#include <string>
#include <string_view>

namespace omnitune {

enum class ConfigIssueKind {
    FileUnreadable,  // the file cannot be opened or read
    ParseError,      // not YAML, or truncated
    NotAConfig,      // YAML, but no OmniTune `schema` key
    UnknownSchema,   // a schema version this build does not read
    MissingKey,      // warning: the key is absent, its default is used
    UnknownKey,      // warning: a key the schema does not know (a typo?)
    WrongType,       // e.g. text where a number belongs
    OutOfRange,      // a number outside the key's range
    Inconsistent,    // keys that contradict each other (low above high, ...)
    MaskError,       // the mask image is missing, unreadable or of the wrong size
    WriteError,      // saving failed
};

std::string_view configIssueKindName(ConfigIssueKind k);

struct ConfigIssue {
    ConfigIssueKind kind = ConfigIssueKind::ParseError;
    std::string file;     // as given by the caller
    int line = 0;         // 1-based, 0 when unknown
    std::string key;      // dotted key path, e.g. "hough.area_bounds"; empty when not about a key
    std::string message;  // what is wrong, in words

    // "config.yml:12: hough.canny_low: 900 is outside 0..1020"
    std::string toString() const;
};

}  // namespace omnitune
