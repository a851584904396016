#pragma once
// Opening YAML held in memory with cv::FileStorage, as every OmniTune file parser does (pure
// parsers take text, not paths). Keeps the line of a parse error, counted in `text`.
#include <opencv2/core.hpp>

#include <optional>
#include <string>

namespace omnitune {

struct YamlParseError {
    int line = 0;         // 1-based in the text given; 0 when OpenCV names none
    std::string message;  // OpenCV's words for the fault
};

// Opens `text` for reading into `fs`; nothing on success, else the parse error. A text without
// the "%YAML" directive is accepted (OpenCV needs it from memory; it is added and the line
// numbers corrected).
std::optional<YamlParseError> openYamlText(const std::string& text, cv::FileStorage& fs);

// Where `value` holds a character cv::FileStorage cannot write and read back (a control
// character other than tab, newline and carriage return, e.g. from an escape like "\1"), or
// std::string::npos. Parsers refuse such text so that every file they load saves back readable.
std::size_t findUnsavableCharacter(const std::string& value);

}  // namespace omnitune
