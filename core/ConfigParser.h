#pragma once
// Reading config.yml. parseConfig() is pure (text in, config plus typed warnings out);
// loadConfig() adds the file and the mask image beside it.
#include "core/Config.h"
#include "core/ConfigIssue.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct ConfigLoad {
    Config config;                     // meaningful only when ok()
    std::vector<ConfigIssue> warnings; // missing keys (defaults used), unknown keys
    std::optional<ConfigIssue> error;  // the first fault; loading stops there

    bool ok() const { return !error.has_value(); }
};

// `fileName` only labels the messages. Does not read the mask image.
ConfigLoad parseConfig(const std::string& text, const std::string& fileName);

// Reads `path`, parses it and loads geometry.mask_file relative to the file's folder.
ConfigLoad loadConfig(const std::string& path);

}  // namespace omnitune
