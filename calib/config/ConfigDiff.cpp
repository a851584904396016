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
        if (a != b) changes.push_back({k.path, std::move(a), std::move(b), {}});
    }
    if (from.colors.classes != to.colors.classes) {
        auto names = [](const ColourClasses& classes) {
            std::string s;
            for (const ColourClassDef& c : classes) s += (s.empty() ? "" : ", ") + c.name;
            return std::to_string(classes.size()) + " classes (" + s + ")";
        };
        std::string before = names(from.colors.classes);
        std::string after = names(to.colors.classes);
        if (before == after) after += ", boxes or roles edited";
        changes.push_back({"colors.classes", std::move(before), std::move(after), to.colors.classes});
    }
    return changes;
}

}  // namespace omnitune
