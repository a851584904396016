#pragma once
// Writing config.yml: every schema key with a comment giving its unit and range.
#include "core/Config.h"
#include "core/ConfigIssue.h"

#include <optional>
#include <string>

namespace omnitune {

std::string serializeConfig(const Config& config);

// Atomic save: writes `path`.tmp, flushes it to disk, keeps the previous file as `path`.bak
// and renames the new one over `path`. Writes config.mask to geometry.mask_file (relative to
// the config's folder) the same way. The config is checked first; nothing is written when
// it is not valid. Returns the fault, or nothing on success.
// `keepBackup`: the previous config (and mask) are kept as .bak files first.
std::optional<ConfigIssue> saveConfig(const Config& config, const std::string& path, bool keepBackup = true);

// Writes `bytes` to `path` atomically (temp file, flush, rename), with a `path`.bak of the
// previous file when `keepBackup`; on failure returns a message and leaves `path` as it was.
std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes,
                                               bool keepBackup = true);

}  // namespace omnitune
