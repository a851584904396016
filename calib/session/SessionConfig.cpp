#include "calib/session/SessionConfig.h"

#include "calib/session/Session.h"

#include <filesystem>

namespace omnitune {

namespace fs = std::filesystem;

namespace {

// Whether `inner` is `outer` or lies below it; both canonical.
bool isInside(const fs::path& inner, const fs::path& outer)
{
    auto o = outer.begin();
    auto i = inner.begin();
    for (; o != outer.end(); ++o, ++i)
        if (i == inner.end() || *i != *o) return false;
    return true;
}

}  // namespace

SessionConfigChoice sessionConfigPath(const std::string& folder, const std::string& configFile,
                                      const std::string& infoFile)
{
    SessionConfigChoice out;
    const fs::path dir(folder);
    std::error_code ec;
    if (configFile.empty()) {  // config.yml, under the same inside-the-folder rule as a named file
        const fs::path fallback = dir / kSessionConfigFile;
        if (!fs::is_regular_file(fallback, ec)) return out;
        const fs::path realDir = fs::canonical(dir, ec);
        const fs::path realFile = ec ? fs::path() : fs::canonical(fallback, ec);
        if (ec || !isInside(realFile, realDir)) {
            out.issue = SessionIssue{SessionIssueKind::MissingConfig, infoFile, 0, std::string(kSessionConfigFile),
                                     "leads outside the session folder (a link?): a session may only use a config "
                                     "inside it; the session has no config"};
            return out;
        }
        out.path = fallback.string();
        return out;
    }
    auto refuse = [&](const std::string& why) {
        out.issue = SessionIssue{SessionIssueKind::MissingConfig, infoFile, 0, "config_file",
                                 "names \"" + configFile + "\", " + why + "; the session has no config"};
        return out;
    };
    const fs::path named(configFile);
    if (named.is_absolute())
        return refuse("an absolute path: a session may only name a file inside its folder");
    for (const fs::path& part : named)
        if (part == "..") return refuse("which leaves the session folder: a session may only name a file inside it");
    const fs::path candidate = dir / named;
    if (!fs::exists(candidate, ec)) return refuse("which is not in the session folder");
    // A symbolic link inside the folder may still point out of it.
    const fs::path realDir = fs::canonical(dir, ec);
    const fs::path realFile = ec ? fs::path() : fs::canonical(candidate, ec);
    if (ec || !isInside(realFile, realDir))
        return refuse("which leads outside the session folder (a link?): a session may only name a file inside it");
    if (!fs::is_regular_file(realFile, ec)) return refuse("which is not a regular file");
    out.path = candidate.string();
    return out;
}

}  // namespace omnitune
