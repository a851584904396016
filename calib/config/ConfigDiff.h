#pragma once
// What differs between two configs, key by key over the schema (ConfigSchema.h), in schema
// order. The window's crash recovery lists it ("hough.canny_low: 60 → 75") and restores it.
// The mask image is not a schema key and is not compared.
#include "core/Config.h"
#include "core/ConfigSchema.h"

#include <string>
#include <vector>

namespace omnitune {

struct ConfigChange {
    std::string key;    // schema path, "hough.canny_low"
    ConfigValue from;   // the value in the first config
    ConfigValue to;     // the value in the second

    // "hough.canny_low: 60 → 75"
    std::string toString() const;
};

std::vector<ConfigChange> diffConfigs(const Config& from, const Config& to);

}  // namespace omnitune
