#pragma once
// Writing config.yml: every schema key with a comment giving its unit and range.
#include "core/AtomicFile.h"
#include "core/Config.h"
#include "core/ConfigIssue.h"

#include <optional>
#include <string>

namespace omnitune {

// Numbers are written in the shortest form that reads back to the same double (0.3, not
// 2.9999999999999999e-01), so a saved file is readable and loads exactly what was saved.
std::string serializeConfig(const Config& config);

// Atomic save (core/AtomicFile.h): the config and its mask image (config.mask, to
// geometry.mask_file relative to the config's folder) are both written to temporaries and
// flushed before either replaces its old version, under the folder's save lock. The config is
// checked first; nothing is written when it is not valid. Returns the fault, or nothing.
// `keepBackup`: FILE.bak keeps the file as it was before OmniTune first replaced it.
std::optional<ConfigIssue> saveConfig(const Config& config, const std::string& path, bool keepBackup = true);

}  // namespace omnitune
