#include "core/FileIssue.h"

namespace omnitune {

std::string FileIssue::toString() const
{
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line);
    if (!s.empty()) s += ": ";
    if (!key.empty()) s += key + ": ";
    return s + message;
}

}  // namespace omnitune
