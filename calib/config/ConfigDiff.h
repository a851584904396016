#pragma once
// What differs between two configs, key by key over the schema (ConfigSchema.h), in schema
// order, then the colour classes (a list, not a schema key) as one change "colors.classes". The
// window's crash recovery lists it ("hough.canny_low: 60 → 75") and restores it. The mask image
// is not compared.
#include "core/Config.h"
#include "core/ConfigSchema.h"

#include <string>
#include <vector>

namespace omnitune {

struct ConfigChange {
    std::string key;    // schema path, "hough.canny_low", or "colors.classes"
    ConfigValue from;   // the value in the first config (colors.classes: a summary text)
    ConfigValue to;     // the value in the second
    ColourClasses classes;  // colors.classes: the second config's classes

    // "hough.canny_low: 60 → 75"
    std::string toString() const;
};

std::vector<ConfigChange> diffConfigs(const Config& from, const Config& to);

}  // namespace omnitune
