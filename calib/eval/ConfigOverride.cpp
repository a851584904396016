#include "calib/eval/ConfigOverride.h"

#include "core/ConfigSchema.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace omnitune {

namespace {

std::string trimmed(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

std::optional<double> number(const std::string& text)
{
    const std::string t = trimmed(text);
    if (t.empty()) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(t.c_str(), &end);
    if (errno != 0 || end != t.c_str() + t.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<ConfigValue> parseValue(const ConfigKey& key, const std::string& text)
{
    const std::string t = trimmed(text);
    switch (key.type) {
    case ValueType::Bool:
        if (t == "true" || t == "1") return ConfigValue(true);
        if (t == "false" || t == "0") return ConfigValue(false);
        return std::nullopt;
    case ValueType::Int: {
        const auto v = number(t);
        if (!v || *v != std::floor(*v) || std::abs(*v) > 1e9) return std::nullopt;
        return ConfigValue(int(*v));
    }
    case ValueType::Double:
        if (const auto v = number(t)) return ConfigValue(*v);
        return std::nullopt;
    case ValueType::Text:
        return ConfigValue(t);
    case ValueType::Choice:
        for (const std::string& c : key.choices)
            if (c == t) return ConfigValue(t);
        return std::nullopt;
    case ValueType::DoubleList: {
        if (t.size() < 2 || t.front() != '[' || t.back() != ']') return std::nullopt;
        std::vector<double> list;
        std::stringstream items(t.substr(1, t.size() - 2));
        std::string item;
        while (std::getline(items, item, ',')) {
            const auto v = number(item);
            if (!v) return std::nullopt;
            list.push_back(*v);
        }
        return ConfigValue(list);
    }
    }
    return std::nullopt;
}

bool inRange(const ConfigKey& key, const ConfigValue& v)
{
    auto ok = [&](double x) { return x >= key.min && x <= key.max; };
    if (const int* i = std::get_if<int>(&v)) return ok(*i);
    if (const double* d = std::get_if<double>(&v)) return ok(*d);
    if (const auto* l = std::get_if<std::vector<double>>(&v)) {
        for (double x : *l)
            if (!ok(x)) return false;
    }
    return true;
}

}  // namespace

std::optional<std::string> applyConfigOverride(Config& config, const ConfigOverride& o)
{
    const ConfigKey* key = findConfigKey(o.key);
    if (!key) return "unknown config key '" + o.key + "'";
    const auto value = parseValue(*key, o.value);
    if (!value) return o.key + ": '" + o.value + "' is not a " + std::string(valueTypeName(key->type));
    if (!inRange(*key, *value)) return o.key + ": '" + o.value + "' is outside its range";
    key->set(config, *value);
    return std::nullopt;
}

std::string overrideLabel(const ConfigOverride& o) { return o.key + "=" + o.value; }

std::vector<ConfigOverride> parseDeviationsCsv(const std::string& text, std::string& error)
{
    std::vector<ConfigOverride> rows;
    std::stringstream in(text);
    std::string line;
    int number = 0;
    bool header = false;
    while (std::getline(in, line)) {
        ++number;
        const std::string t = trimmed(line);
        if (t.empty() || t[0] == '#') continue;
        if (!header) {
            if (t.rfind("key,thesis_value", 0) != 0) {
                error = "line " + std::to_string(number) + ": expected the header 'key,thesis_value,why'";
                return {};
            }
            header = true;
            continue;
        }
        const auto c1 = t.find(',');
        if (c1 == std::string::npos) {
            error = "line " + std::to_string(number) + ": expected 'key,thesis_value,why'";
            return {};
        }
        // A list value ("[70, 105]") holds commas of its own: its row's second comma follows the ']'.
        const auto bracket = t.find_first_not_of(" \t", c1 + 1);
        const auto close = bracket != std::string::npos && t[bracket] == '[' ? t.find(']', bracket) : std::string::npos;
        const auto c2 = t.find(',', close == std::string::npos ? c1 + 1 : close);
        ConfigOverride o;
        o.key = trimmed(t.substr(0, c1));
        o.value = trimmed(t.substr(c1 + 1, c2 == std::string::npos ? std::string::npos : c2 - c1 - 1));
        if (c2 != std::string::npos) o.why = trimmed(t.substr(c2 + 1));
        Config probe;
        if (auto why = applyConfigOverride(probe, o)) {
            error = "line " + std::to_string(number) + ": " + *why;
            return {};
        }
        rows.push_back(o);
    }
    if (!header) error = "no header 'key,thesis_value,why'";
    return rows;
}

}  // namespace omnitune
