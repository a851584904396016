#include "calib/session/SessionIssue.h"

namespace omnitune {

std::string_view sessionIssueKindName(SessionIssueKind k)
{
    switch (k) {
    case SessionIssueKind::FileUnreadable: return "file unreadable";
    case SessionIssueKind::ParseError: return "parse error";
    case SessionIssueKind::NotASession: return "not a session";
    case SessionIssueKind::UnknownFormat: return "unknown format";
    case SessionIssueKind::MissingKey: return "missing key";
    case SessionIssueKind::UnknownKey: return "unknown key";
    case SessionIssueKind::WrongType: return "wrong type";
    case SessionIssueKind::OutOfRange: return "out of range";
    case SessionIssueKind::MissingInfo: return "missing session.yml";
    case SessionIssueKind::FrameCountMismatch: return "frame count mismatch";
    case SessionIssueKind::MissingFrames: return "missing frames";
    case SessionIssueKind::TruncatedFrame: return "truncated frame";
    case SessionIssueKind::MissingConfig: return "missing config";
    case SessionIssueKind::BadNumber: return "bad number";
    case SessionIssueKind::WrongColumnCount: return "wrong column count";
    case SessionIssueKind::DuplicateFrame: return "duplicate frame";
    case SessionIssueKind::UnknownColumn: return "unknown column";
    case SessionIssueKind::MissingColumn: return "missing column";
    case SessionIssueKind::BadValue: return "bad value";
    case SessionIssueKind::FrameNotRecorded: return "frame not recorded";
    case SessionIssueKind::FolderNotEmpty: return "folder not empty";
    case SessionIssueKind::WrongFrame: return "wrong frame";
    case SessionIssueKind::WriteError: return "write error";
    }
    return "?";
}

std::string SessionIssue::toString() const
{
    std::string s = file.empty() ? std::string("<session>") : file;
    if (line > 0) s += ":" + std::to_string(line);
    s += ": ";
    if (!key.empty()) s += key + ": ";
    return s + message;
}

}  // namespace omnitune
