#pragma once
// Opening YAML held in memory with cv::FileStorage, as every OmniTune file parser does (pure
// parsers take text, not paths), and the checks OpenCV's reader does not make: input too large
// or nested too deep for it (its recursive parser would overflow the stack), keys written twice
// and integers it would misread (it keeps the first duplicate, wraps 4294967496 to 200 and reads
// 0100 as octal 64).
#include "core/FileIssue.h"

#include <opencv2/core.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace omnitune {

// Limits far above any file OmniTune writes (a config is ~15 KB and 4 levels deep).
inline constexpr std::size_t kMaxYamlBytes = 1024 * 1024;
inline constexpr int kMaxYamlDepth = 64;
// Text values longer than this are refused: OpenCV's YAML reader fails on strings of ~4 KiB.
inline constexpr std::size_t kMaxYamlTextBytes = 1024;

struct YamlParseError {
    int line = 0;         // 1-based in the text given; 0 when none applies
    std::string message;  // what is wrong (OpenCV's words for a syntax error)
};

// Opens `text` for reading into `fs`; nothing on success, else the parse error. Text larger or
// deeper than the limits above is refused before OpenCV sees it. A text without the "%YAML"
// directive is accepted (OpenCV needs it from memory; it is added and the line numbers corrected).
std::optional<YamlParseError> openYamlText(const std::string& text, cv::FileStorage& fs);

// Where `value` holds a character cv::FileStorage cannot write and read back (a control
// character other than tab, newline and carriage return, e.g. from an escape like "\1"), or
// std::string::npos. Parsers refuse such text so that every file they load saves back readable.
std::size_t findUnsavableCharacter(const std::string& value);

// The size and nesting limits alone (openYamlText applies them).
std::optional<YamlParseError> checkYamlShape(const std::string& text);

// A key or section written twice in one section, or an integer OpenCV would read as another
// number (a leading zero, or beyond the int range). Block-style YAML as OmniTune writes it;
// `fs` opened on the same text catches duplicates in any style (line 0 then).
std::optional<FileIssue> checkWrittenValues(const std::string& text, const cv::FileStorage& fs,
                                            const std::string& fileName);

// The line of the first "key:" with the dotted `path` ("camera.gain") in block-style YAML; 0
// when absent. cv::FileNode does not know its line; messages want it.
int yamlLineOfKey(const std::string& text, const std::string& path);

// The shortest text that reads back as exactly `v`, always with a '.' or an exponent so that
// YAML reads a real ("30.0", not "30"; "0.3", not 2.9999999999999999e-01).
std::string yamlNumber(double v);

// `s` in double quotes, escaped as OpenCV's YAML reader unescapes it. Not OpenCV's own writer:
// it leaves a text that starts and ends with a quote unescaped ("Flea2" in quotes came back
// without them; a lone " wrote a file that does not load). Parsers refuse the other control
// characters (findUnsavableCharacter).
std::string yamlQuoted(const std::string& s);

// "an integer", "a number", "text \"abc\"", "a list", "a section", "nothing": for messages.
std::string yamlTypeOf(const cv::FileNode& n);

}  // namespace omnitune
