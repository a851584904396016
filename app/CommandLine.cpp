#include "app/CommandLine.h"

#include <cmath>
#include <cstdlib>

namespace omnitune {

std::optional<std::string> CommandLine::value(const std::string& name) const
{
    const auto it = values.find(name);
    if (it == values.end() || it->second.empty()) return std::nullopt;
    return it->second.back();
}

const std::vector<std::string>& CommandLine::all(const std::string& name) const
{
    static const std::vector<std::string> none;
    const auto it = values.find(name);
    return it == values.end() ? none : it->second;
}

CommandLine parseCommandLine(int argc, const char* const* argv, const std::vector<OptionSpec>& specs)
{
    CommandLine cl;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--", 0) != 0) {
            cl.error = "unexpected argument '" + arg + "'";
            return cl;
        }
        std::string name = arg.substr(2);
        std::optional<std::string> inlineValue;
        if (const auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        const OptionSpec* spec = nullptr;
        for (const auto& s : specs)
            if (s.name == name) spec = &s;
        if (!spec) {
            cl.error = "unknown option '--" + name + "'";
            return cl;
        }
        if (cl.has(name) && !spec->repeatable) {
            cl.error = "option '--" + name + "' given twice";
            return cl;
        }
        if (!spec->takesValue) {
            cl.values[name].push_back("");
            continue;
        }
        if (!inlineValue) {
            if (i + 1 >= argc) {
                cl.error = "option '--" + name + "' needs a value";
                return cl;
            }
            inlineValue = argv[++i];
        }
        cl.values[name].push_back(*inlineValue);
    }
    return cl;
}

std::string usageText(const std::string& program, const std::string& summary, const std::vector<OptionSpec>& specs)
{
    std::string text = "usage: " + program + " [options]\n" + summary + "\n\noptions:\n";
    for (const auto& s : specs) {
        std::string left = "  --" + s.name;
        text += left + std::string(left.size() < 20 ? 20 - left.size() : 1, ' ') + s.help + "\n";
    }
    return text;
}

std::optional<int> parseInt(const std::string& text)
{
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || v < -2147483647L || v > 2147483647L) return std::nullopt;
    return int(v);
}

std::optional<double> parseDouble(const std::string& text)
{
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;  // "nan", "inf" are no numbers
    return v;
}

}  // namespace omnitune
