#include "core/ConfigParser.h"

#include "core/ColourClassesYaml.h"
#include "core/ConfigSchema.h"
#include "core/RegularFile.h"
#include "core/RingCoverage.h"
#include "core/YamlText.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <filesystem>
#include <set>

namespace omnitune {

namespace {

// Reads one key's node into a value, or explains why it cannot.
std::optional<ConfigValue> readValue(const ConfigKey& k, const cv::FileNode& n, std::string& why)
{
    switch (k.type) {
    case ValueType::Int:
        if (n.isInt()) return ConfigValue(int(n));
        break;
    case ValueType::Double:
        if (n.isInt() || n.isReal()) return ConfigValue(double(n));
        break;
    case ValueType::Bool:
        if (n.isInt() && (int(n) == 0 || int(n) == 1)) return ConfigValue(int(n) == 1);
        if (n.isString() && (std::string(n) == "true" || std::string(n) == "false"))
            return ConfigValue(std::string(n) == "true");
        break;
    case ValueType::Text:
        if (n.isString()) {
            const std::string s(n);
            if (findUnsavableCharacter(s) == std::string::npos) return ConfigValue(s);
            why = "contains a control character (at " + std::to_string(findUnsavableCharacter(s)) +
                  "), which could not be saved back";
            return std::nullopt;
        }
        break;
    case ValueType::Choice:
        if (n.isString()) {
            const std::string s(n);
            for (const auto& c : k.choices)
                if (c == s) return ConfigValue(s);
            std::string all;
            for (const auto& c : k.choices) all += (all.empty() ? "" : ", ") + c;
            why = "\"" + s + "\" is not one of " + all;
            return std::nullopt;
        }
        break;
    case ValueType::DoubleList:
        if (n.isSeq()) {
            std::vector<double> v;
            for (const cv::FileNode& e : n) {
                if (!e.isInt() && !e.isReal()) {
                    why = "expected a list of numbers, found " + yamlTypeOf(e) + " in it";
                    return std::nullopt;
                }
                v.push_back(double(e));
            }
            return ConfigValue(v);
        }
        break;
    }
    why = "expected " + std::string(k.type == ValueType::Bool ? "0/1 or true/false" : valueTypeName(k.type)) +
          ", found " + yamlTypeOf(n);
    return std::nullopt;
}

// Leaf keys present in the file but unknown to the schema.
void collectUnknown(const cv::FileNode& node, const std::string& prefix, bool oldColourForm,
                    std::vector<std::string>& unknown)
{
    static const std::set<std::string> topLevel = {"schema", "saved_by", "complete"};
    for (const cv::FileNode& child : node) {
        const std::string path = prefix.empty() ? child.name() : prefix + "." + child.name();
        if (prefix.empty() && topLevel.count(path)) continue;
        if (findConfigKey(path) || isColourClassesPath(path, oldColourForm)) continue;
        if (child.isMap()) {
            collectUnknown(child, path, oldColourForm, unknown);
            continue;
        }
        unknown.push_back(path);
    }
}

}  // namespace

ConfigLoad parseConfig(const std::string& text, const std::string& fileName)
{
    ConfigLoad out;
    auto fail = [&](ConfigIssueKind kind, const std::string& key, const std::string& message) {
        out.error = ConfigIssue{kind, fileName, 0, key, message};
        return out;
    };
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
        return fail(ConfigIssueKind::ParseError, "", "the file is empty");

    cv::FileStorage fs;
    if (const auto err = openYamlText(text, fs)) {
        out.error = ConfigIssue{ConfigIssueKind::ParseError, fileName, err->line, "", "not a valid YAML config: " + err->message};
        return out;
    }
    if (auto misread = checkWrittenValues(text, fs, fileName)) {
        out.error = misread;
        return out;
    }
    const cv::FileNode root = fs.root();
    if (!root.isMap()) return fail(ConfigIssueKind::NotAConfig, "", "the top level is not a map of sections");

    const cv::FileNode schema = root["schema"];
    if (schema.empty() || schema.isNone())
        return fail(ConfigIssueKind::NotAConfig, "schema", "no 'schema' key: this is not an OmniTune config");
    if (!schema.isInt()) return fail(ConfigIssueKind::WrongType, "schema", "expected an integer, found " + yamlTypeOf(schema));
    if (int(schema) != kConfigSchemaVersion)
        return fail(ConfigIssueKind::UnknownSchema, "schema",
                    "schema " + std::to_string(int(schema)) + " is not known to this build, which reads schema " +
                        std::to_string(kConfigSchemaVersion));
    // Upgrades of older schemas would run here, one numbered step at a time (none exist yet).

    if (!root["saved_by"].empty() && root["complete"].empty())
        return fail(ConfigIssueKind::ParseError, "complete",
                    "the file ends early (no 'complete' marker after the last section): it was cut short");

    for (const ConfigKey& k : configSchema()) {
        cv::FileNode n = root;
        for (const std::string& part : splitConfigPath(k.path)) {
            if (!n.isMap()) {
                n = cv::FileNode();
                break;
            }
            n = n[part];
        }
        if (n.empty() || n.isNone()) {
            out.warnings.push_back({ConfigIssueKind::MissingKey, fileName, 0, k.path,
                                    "missing, using the default " + formatConfigValue(k.get(out.config))});
            continue;
        }
        std::string why;
        const auto value = readValue(k, n, why);
        if (!value) return fail(ConfigIssueKind::WrongType, k.path, why);
        k.set(out.config, *value);
    }
    // The class list is no scalar key: its own reader (which also reads the old per-class keys).
    ColourClassesRead classes = readColourClasses(root["colors"], text, fileName);
    if (classes.error) {
        out.error = classes.error;
        return out;
    }
    out.config.colors.classes = std::move(classes.classes);
    for (ConfigIssue& w : classes.warnings) out.warnings.push_back(std::move(w));
    std::vector<std::string> unknown;
    collectUnknown(root, "", classes.oldForm, unknown);
    for (const std::string& u : unknown)
        out.warnings.push_back({ConfigIssueKind::UnknownKey, fileName, 0, u, "unknown key, ignored (a typo?)"});

    const auto problems = checkConfig(out.config, fileName);
    if (!problems.empty()) out.error = problems.front();
    return out;
}

ConfigLoad loadConfig(const std::string& path)
{
    ConfigLoad out;
    std::string why;
    const auto text = readRegularFile(path, kMaxYamlBytes, why);
    if (!text) {
        out.error = ConfigIssue{ConfigIssueKind::FileUnreadable, path, 0, "", why};
        return out;
    }
    out = parseConfig(*text, path);
    if (!out.ok() || out.config.geometry.maskFile.empty()) return out;

    const auto maskPath = (std::filesystem::path(path).parent_path() / out.config.geometry.maskFile).string();
    cv::Mat mask;
    const auto notRegular = checkRegularFile(maskPath);
    try {
        if (!notRegular) mask = cv::imread(maskPath, cv::IMREAD_GRAYSCALE);
    } catch (const cv::Exception&) {
        mask.release();
    }
    if (mask.empty()) {
        out.error = ConfigIssue{ConfigIssueKind::MaskError, path, 0, "geometry.mask_file",
                                "cannot read the mask image " + maskPath + (notRegular ? ": " + *notRegular : "")};
        return out;
    }
    out.config.mask = mask;
    const auto problems = checkConfig(out.config, path);
    if (!problems.empty()) {
        out.error = problems.front();
        return out;
    }
    // A mask of the opposite convention (black = process) loads as "almost nothing processed":
    // say so instead of letting every pane go quiet.
    if (const double share = maskProcessedShare(mask, out.config.geometry); share < kRingMostlyOffImageShare) {
        char pct[16];
        std::snprintf(pct, sizeof pct, "%.0f", 100.0 * share);
        out.warnings.push_back(ConfigIssue{
            ConfigIssueKind::MaskError, path, 0, "geometry.mask_file",
            "the mask " + maskPath + " lets only " + pct +
                " % of the ring between inner_radius and outer_radius be processed (white = process); if it was made "
                "the other way round, convert it: omnitune-calibrate mask --import FILE --process black"});
    }
    return out;
}

}  // namespace omnitune
