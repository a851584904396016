#include "core/YamlText.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <vector>

namespace omnitune {

namespace {

// One line of block-style YAML as a reader sees its structure, without OpenCV.
struct OutlineLine {
    int line = 0;
    int depth = 0;                     // sections, list items and open brackets around its deepest point
    std::string path;                  // dotted key path of the key on this line, or of the key above it
    bool hasKey = false;               // the line starts "key:"
    int indent = -1;                   // columns before its content; -1 inside a [ ] or { } spanning lines
    bool stray = false;                // none of the line kinds below (OmniTune never writes one)
    std::vector<std::string> scalars;  // its plain (unquoted) values, e.g. "200" or the elements of [ 1, 2 ]
};

bool startsScalar(char previous) { return previous == 0 || std::string_view(":-[{,").find(previous) != std::string_view::npos; }

// Splits `text` into OutlineLines, stopping after the first line deeper than `maxDepth`.
std::vector<OutlineLine> outline(const std::string& text, int maxDepth)
{
    struct Open {
        std::size_t column;
        std::string key;  // "#line.column" for a list item (items are distinct, never duplicates)
    };
    std::vector<OutlineLine> out;
    std::vector<Open> open;  // the block sections and list items the current line is inside
    int flow = 0;            // open [ and { (a flow collection may span lines)
    int lineNo = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + start, end - start);
        start = end + 1;
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        OutlineLine o;
        o.line = lineNo;
        std::size_t pos = line.find_first_not_of(' ');
        if (pos == std::string_view::npos || line[pos] == '#') continue;
        if (flow == 0) {
            // Directives on the first line, document markers alone on theirs.
            if (pos == 0 && line[0] == '%') {
                if (lineNo == 1) continue;
                o.stray = true;
            } else if (pos == 0 && (line.substr(0, 3) == "---" || line.substr(0, 3) == "...")) {
                const std::size_t rest = line.find_first_not_of(' ', 3);
                if (rest == std::string_view::npos || line[rest] == '#') continue;
                o.stray = true;
            }
            o.indent = int(pos);
            bool listItem = false;
            while (!open.empty() && open.back().column >= pos) open.pop_back();
            // "- " list items nest one level each, even on one line ("- - - x").
            while (pos < line.size() && line[pos] == '-' && (pos + 1 == line.size() || line[pos + 1] == ' ')) {
                open.push_back({pos, "#" + std::to_string(lineNo) + "." + std::to_string(pos)});
                listItem = true;
                pos = line.find_first_not_of(' ', pos + 1);
                if (pos == std::string_view::npos) pos = line.size();
            }
            // "key:" then a space or the end of the line (quoted keys are not used by OmniTune).
            const std::size_t colon = line.find(':', pos);
            if (colon != std::string_view::npos && line.find_first_of("[]{}\"'#,", pos) > colon &&
                (colon + 1 == line.size() || line[colon + 1] == ' ')) {
                std::string key(line.substr(pos, colon - pos));
                key.erase(key.find_last_not_of(' ') + 1);
                for (const Open& s : open)
                    if (!s.key.empty()) o.path += s.key + ".";
                o.path += key;
                o.hasKey = true;
                open.push_back({pos, key});
                pos = colon + 1;
            }
            // Else a value on a line of its own: a flow collection or a quoted text may start one.
            if (!o.hasKey && !listItem && std::string_view("[{\"'").find(line[pos]) == std::string_view::npos)
                o.stray = true;
        } else {
            pos = 0;
        }
        if (!o.hasKey)  // a value line of the key above it (a list continued, a list item)
            for (const Open& s : open)
                if (!s.key.empty() && s.key[0] != '#') o.path += (o.path.empty() ? "" : ".") + s.key;
        // The values: brackets, quotes, comments and plain scalars.
        int deepest = flow;
        std::string scalar;
        char previous = 0;  // last significant character, to tell a quote that opens a scalar
        auto endScalar = [&] {
            const auto first = scalar.find_first_not_of(' ');
            if (first != std::string::npos) o.scalars.push_back(scalar.substr(first, scalar.find_last_not_of(' ') + 1 - first));
            scalar.clear();
        };
        for (std::size_t i = pos; i < line.size(); ++i) {
            const char c = line[i];
            if (c == '#' && (i == 0 || line[i - 1] == ' ')) break;
            if ((c == '"' || c == '\'') && startsScalar(previous) && scalar.find_first_not_of(' ') == std::string::npos) {
                // A quoted scalar: skip to its closing quote (\" escapes in "...", '' in '...').
                for (++i; i < line.size(); ++i) {
                    if (c == '"' && line[i] == '\\') ++i;
                    else if (line[i] == c && !(c == '\'' && i + 1 < line.size() && line[i + 1] == '\'')) break;
                    else if (c == '\'' && line[i] == '\'') ++i;
                }
                scalar.clear();
                previous = c;
                continue;
            }
            if (c == '[' || c == '{') {
                endScalar();
                deepest = std::max(deepest, ++flow);
            } else if (c == ']' || c == '}') {
                endScalar();
                flow = std::max(0, flow - 1);
            } else if (c == ',') {
                endScalar();
            } else if (c == ':' && flow > 0 && (i + 1 == line.size() || line[i + 1] == ' ')) {
                scalar.clear();  // "key: value" inside { }: the key is not a value
            } else {
                scalar += c;
            }
            if (c != ' ') previous = c;
        }
        endScalar();
        o.depth = int(open.size()) + deepest;
        out.push_back(std::move(o));
        if (out.back().depth > maxDepth) break;
    }
    return out;
}

// Why OpenCV would read the plain scalar `s` as another integer than written, or nothing.
// (No std::regex: its recursive matcher overflows the stack on a long token.)
std::optional<std::string> misreadInteger(const std::string& s)
{
    const std::size_t sign = s.empty() || (s[0] != '-' && s[0] != '+') ? 0 : 1;
    const bool isHex = s.size() > sign + 2 && s[sign] == '0' && (s[sign + 1] == 'x' || s[sign + 1] == 'X');
    const std::size_t digits = sign + (isHex ? 2 : 0);
    if (s.size() == digits) return std::nullopt;
    for (std::size_t i = digits; i < s.size(); ++i)
        if (!(isHex ? std::isxdigit(static_cast<unsigned char>(s[i])) : std::isdigit(static_cast<unsigned char>(s[i]))))
            return std::nullopt;  // not an integer: a real, text, ...
    if (!isHex && s.size() > digits + 1 && s[digits] == '0') {
        const std::string octal = s.size() - digits < 12 ? std::to_string(std::strtoll(s.c_str(), nullptr, 8)) : "?";
        return s + " has a leading zero, which YAML reads as an octal number (" + octal + "); write it without the zero";
    }
    errno = 0;
    const long long v = std::strtoll(s.c_str(), nullptr, 0);
    if (errno == ERANGE || v < INT_MIN || v > INT_MAX)
        return (s.size() > 40 ? s.substr(0, 40) + "..." : s) + " is beyond the integer range " + std::to_string(INT_MIN) +
               ".." + std::to_string(INT_MAX);
    return std::nullopt;
}

// A key that appears twice in one map of the parsed tree (any YAML style).
std::optional<std::string> duplicateIn(const cv::FileNode& node, const std::string& prefix)
{
    if (!node.isMap() && !node.isSeq()) return std::nullopt;
    std::set<std::string> names;
    int index = 0;
    for (const cv::FileNode& child : node) {
        const std::string name = node.isMap() ? child.name() : std::to_string(index++);
        const std::string path = prefix.empty() ? name : prefix + "." + name;
        if (node.isMap() && !names.insert(name).second) return path;
        if (auto inner = duplicateIn(child, path)) return inner;
    }
    return std::nullopt;
}

}  // namespace

std::optional<YamlParseError> checkYamlShape(const std::string& text)
{
    if (text.size() > kMaxYamlBytes)
        return YamlParseError{0, "is " + std::to_string(text.size() / 1024) + " KiB; OmniTune reads YAML files up to " +
                                     std::to_string(kMaxYamlBytes / 1024) + " KiB"};
    // YAML allows no control character but tab, newline and carriage return; OpenCV's reader
    // loops for good on some (":---" then \x04, found by fuzz/fuzz_config).
    if (const std::size_t at = findUnsavableCharacter(text); at != std::string::npos)
        return YamlParseError{int(std::count(text.begin(), text.begin() + long(at), '\n')) + 1,
                              "holds a control character (byte " + std::to_string(int(static_cast<unsigned char>(text[at]))) +
                                  "): not a YAML text file; refused before parsing"};
    const std::vector<OutlineLine> lines = outline(text, kMaxYamlDepth);
    if (!lines.empty() && lines.back().depth > kMaxYamlDepth)
        return YamlParseError{lines.back().line, "nested more than " + std::to_string(kMaxYamlDepth) +
                                                     " levels deep (sections, list items and brackets); refused before parsing"};
    // A line left of the document's first one is invalid YAML, and OpenCV's reader loops for
    // good on some ("  t: 1" then "x---", found by fuzz/fuzz_config).
    int firstIndent = -1;
    for (const OutlineLine& o : lines) {
        if (o.indent < 0) continue;
        if (firstIndent < 0) firstIndent = o.indent;
        else if (o.indent < firstIndent)
            return YamlParseError{o.line, "Incorrect indentation: left of the first line (" + std::to_string(firstIndent) +
                                              " spaces in); refused before parsing"};
    }
    // OmniTune's YAML is "key: value" lines, "- value" list items and [ ] / { } values; OpenCV's
    // reader loops for good on some other lines ("\xba t -" below "--- a: 1", found by
    // fuzz/fuzz_config), so anything else is refused before it sees them.
    for (const OutlineLine& o : lines)
        if (o.stray)
            return YamlParseError{o.line, "neither \"key: value\" nor a list item \"- value\"; refused before parsing"};
    return std::nullopt;
}

std::optional<YamlParseError> openYamlText(const std::string& text, cv::FileStorage& fs)
{
    if (auto tooMuch = checkYamlShape(text)) return tooMuch;
    const bool hasDirective = text.rfind("%YAML", 0) == 0;
    try {
        fs.open(hasDirective ? text : "%YAML:1.0\n" + text,
                cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    } catch (const cv::Exception& e) {
        // OpenCV's parse errors read "...(line): message" in several shapes.
        YamlParseError err{0, e.err};
        std::smatch m;
        const std::string msg = e.msg;
        if (std::regex_search(msg, m, std::regex(R"(\((\d+)\): ([^\n]*))"))) {
            err.line = std::max(0, std::stoi(m[1]) - (hasDirective ? 0 : 1));
            err.message = m[2];
        }
        return err;
    } catch (const std::exception& e) {
        // OpenCV's reader also fails with other exceptions, e.g. std::length_error on "  : 1".
        return YamlParseError{0, std::string("malformed YAML (the reader failed: ") + e.what() + ")"};
    }
    if (!fs.isOpened()) return YamlParseError{0, "not YAML"};
    return std::nullopt;
}

std::size_t findUnsavableCharacter(const std::string& value)
{
    for (std::size_t i = 0; i < value.size(); ++i) {
        const auto c = static_cast<unsigned char>(value[i]);
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') return i;
    }
    return std::string::npos;
}

std::optional<FileIssue> checkWrittenValues(const std::string& text, const cv::FileStorage& fs,
                                            const std::string& fileName)
{
    std::map<std::string, int> firstLine;
    for (const OutlineLine& o : outline(text, INT_MAX)) {
        if (o.hasKey) {
            const auto [it, isNew] = firstLine.emplace(o.path, o.line);
            if (!isNew)
                return FileIssue{FileIssueKind::DuplicateKey, fileName, o.line, o.path,
                                 "written twice (first on line " + std::to_string(it->second) +
                                     "); a key or section may appear once"};
        }
        for (const std::string& s : o.scalars)
            if (auto why = misreadInteger(s)) return FileIssue{FileIssueKind::OutOfRange, fileName, o.line, o.path, *why};
    }
    if (auto path = duplicateIn(fs.root(), ""))
        return FileIssue{FileIssueKind::DuplicateKey, fileName, 0, *path, "written twice; a key or section may appear once"};
    return std::nullopt;
}

int yamlLineOfKey(const std::string& text, const std::string& path)
{
    for (const OutlineLine& o : outline(text, INT_MAX))
        if (o.hasKey && o.path == path) return o.line;
    return 0;
}

std::string yamlTypeOf(const cv::FileNode& n)
{
    if (n.isInt()) return "an integer";
    if (n.isReal()) return "a number";
    if (n.isString()) return "text \"" + std::string(n) + "\"";
    if (n.isSeq()) return "a list";
    if (n.isMap()) return "a section";
    return "nothing";
}

std::string yamlNumber(double v)
{
    char buf[64];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    std::string s(buf, end);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

std::string yamlQuoted(const std::string& s)
{
    std::string out = "\"";
    for (const char c : s) {
        switch (c) {
        case '\\': out += "\\\\"; break;
        case '"': out += "\\\""; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default: out += c;
        }
    }
    return out + "\"";
}

}  // namespace omnitune
