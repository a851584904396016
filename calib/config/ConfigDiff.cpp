#include "calib/config/ConfigDiff.h"

namespace omnitune {

std::string ConfigChange::toString() const
{
    return key + ": " + formatConfigValue(from) + " \u2192 " + formatConfigValue(to);
}

std::vector<ConfigChange> diffConfigs(const Config& from, const Config& to)
{
    std::vector<ConfigChange> changes;
    for (const ConfigKey& k : configSchema()) {
        ConfigValue a = k.get(from);
        ConfigValue b = k.get(to);
        if (a != b) changes.push_back({k.path, std::move(a), std::move(b)});
    }
    return changes;
}

}  // namespace omnitune
