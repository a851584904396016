#pragma once
// The config a command-line tool runs with: --config FILE, else the session's config by the
// rule every tool and the window share (calib/session/SessionConfig.h); --algorithm overrides
// the file's choice. Warnings go to stderr; an error is one line. `usedPath` receives the file read.
#include "core/Config.h"

#include <optional>
#include <string>

namespace omnitune {

// OpenCV's own log lines (video backends probing a file) would break the tools' one-line errors.
void quietOpenCvLogs();

std::optional<Config> loadToolConfig(const std::optional<std::string>& configPath, const std::string& inputPath,
                                     const std::optional<std::string>& algorithm, std::string& error,
                                     std::string* usedPath = nullptr);

}  // namespace omnitune
