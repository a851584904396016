#pragma once
// A small command-line parser shared by the tools: declared `--name value` options and
// `--flag`s, repeatable options, and one-line errors naming the bad argument.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct OptionSpec {
    std::string name;       // without the dashes
    bool takesValue = true;
    bool repeatable = false;
    std::string help;       // "FILE  the detector config"
};

struct CommandLine {
    std::map<std::string, std::vector<std::string>> values;  // option -> values (flags: one "")
    std::string error;                                        // set when the arguments are bad

    bool has(const std::string& name) const { return values.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;
    const std::vector<std::string>& all(const std::string& name) const;
};

CommandLine parseCommandLine(int argc, const char* const* argv, const std::vector<OptionSpec>& specs);
std::string usageText(const std::string& program, const std::string& summary, const std::vector<OptionSpec>& specs);

// Number arguments: the value, or nullopt when it is not a (finite) number (the caller names the option).
std::optional<int> parseInt(const std::string& text);
std::optional<double> parseDouble(const std::string& text);

}  // namespace omnitune
