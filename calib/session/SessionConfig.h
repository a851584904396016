#pragma once
// Which config a session runs with: one rule for the reader (and so the window),
// omnitune-detect and omnitune-eval, so one session never runs with two configs.
//   - session.yml's config_file when it names one: a relative path that stays inside the
//     session folder (after following symbolic links) and names a regular file;
//   - else config.yml in the folder when it is there;
//   - else none.
// A config_file that is absolute, leaves the folder ("../x.yml", a link to /etc/passwd) or is
// missing gives no config and an issue saying why; it never falls back to config.yml, which
// would run the session with a config it does not name.
#include "calib/session/SessionIssue.h"

#include <optional>
#include <string>

namespace omnitune {

struct SessionConfigChoice {
    std::string path;                   // the config file to use; empty when none
    std::optional<SessionIssue> issue;  // why config_file was not used (MissingConfig), when it was given
};

// `configFile` is session.yml's config_file ("" when absent); `infoFile` labels the issue.
SessionConfigChoice sessionConfigPath(const std::string& folder, const std::string& configFile,
                                      const std::string& infoFile);

}  // namespace omnitune
