#pragma once
// The config schema, declared once: every key of config.yml with its type, unit, range and
// meaning, and how to read and write it in a Config. The loader, the writer, checkConfig(),
// the threshold panel's tooltips and docs/config.md all come from this table.
#include "core/Config.h"
#include "core/ConfigIssue.h"

#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace omnitune {

inline constexpr int kConfigSchemaVersion = 1;

enum class ValueType { Int, Double, Bool, Text, Choice, DoubleList };
std::string_view valueTypeName(ValueType t);

using ConfigValue = std::variant<int, double, bool, std::string, std::vector<double>>;

struct ConfigKey {
    std::string path;  // dotted: "hough.canny_low"
    ValueType type = ValueType::Int;
    std::string unit;  // "px", "%", "m", ... ; empty for none
    double min = 0.0;  // numbers and list elements
    double max = 0.0;
    std::string meaning;               // one line; also the GUI tooltip
    std::vector<std::string> choices;  // ValueType::Choice
    bool fromThesis = false;           // the default is a number published in the thesis
    std::function<ConfigValue(const Config&)> get;
    std::function<void(Config&, const ConfigValue&)> set;
};

const std::vector<ConfigKey>& configSchema();
// "colors.green.h_min" -> {"colors", "green", "h_min"}: the sections a key is nested in.
std::vector<std::string> splitConfigPath(const std::string& path);
const ConfigKey* findConfigKey(std::string_view path);

// Value as written in docs and messages ("60", "0.15", "[70, 105]", "combined").
std::string formatConfigValue(const ConfigValue& v);

// Range and cross-key checks of an in-memory config; empty when it is usable. The loader,
// the command-line tools and the GUI all call this one validator.
std::vector<ConfigIssue> checkConfig(const Config& config, const std::string& file = {});

// docs/config.md, generated from the schema (a test keeps the file in step).
std::string configSchemaMarkdown();

}  // namespace omnitune
