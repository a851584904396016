#include "core/ConfigIssue.h"

namespace omnitune {

std::string_view configIssueKindName(ConfigIssueKind k)
{
    switch (k) {
    case ConfigIssueKind::FileUnreadable: return "file unreadable";
    case ConfigIssueKind::ParseError: return "parse error";
    case ConfigIssueKind::NotAConfig: return "not an OmniTune config";
    case ConfigIssueKind::UnknownSchema: return "unknown schema";
    case ConfigIssueKind::MissingKey: return "missing key";
    case ConfigIssueKind::UnknownKey: return "unknown key";
    case ConfigIssueKind::WrongType: return "wrong type";
    case ConfigIssueKind::OutOfRange: return "out of range";
    case ConfigIssueKind::Inconsistent: return "inconsistent";
    case ConfigIssueKind::MaskError: return "mask error";
    case ConfigIssueKind::WriteError: return "write error";
    }
    return "?";
}

std::string ConfigIssue::toString() const
{
    std::string s = file.empty() ? std::string("<config>") : file;
    if (line > 0) s += ":" + std::to_string(line);
    s += ": ";
    if (!key.empty()) s += key + ": ";
    return s + message;
}

}  // namespace omnitune
