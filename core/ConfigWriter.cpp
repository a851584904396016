#include "core/ConfigWriter.h"

#include "core/ColourClassesYaml.h"
#include "core/ConfigSchema.h"
#include "core/YamlText.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <filesystem>

namespace omnitune {

namespace {

std::string comment(const ConfigKey& k)
{
    std::string c = " " + k.meaning;
    if (k.type == ValueType::Int || k.type == ValueType::Double || k.type == ValueType::DoubleList) {
        char range[96];
        std::snprintf(range, sizeof range, " [%g..%g%s%s]", k.min, k.max, k.unit.empty() ? "" : " ", k.unit.c_str());
        c += range;
    } else if (k.type == ValueType::Bool) {
        c += " [0/1]";
    }
    return c;
}

std::string valueText(const ConfigValue& v)
{
    if (const int* i = std::get_if<int>(&v)) return std::to_string(*i);
    if (const double* d = std::get_if<double>(&v)) return yamlNumber(*d);
    if (const bool* b = std::get_if<bool>(&v)) return *b ? "1" : "0";
    if (const std::string* s = std::get_if<std::string>(&v)) return yamlQuoted(*s);
    std::string list = "[";
    for (double d : std::get<std::vector<double>>(v)) list += (list.size() > 1 ? ", " : " ") + yamlNumber(d);
    return list + " ]";
}

}  // namespace

std::string serializeConfig(const Config& config)
{
    // Written by hand rather than by cv::FileStorage, whose doubles carry 17 digits.
    std::string out = "%YAML:1.0\n---\n#  OmniTune detector configuration. Reference: docs/config.md\n";
    out += "schema: " + std::to_string(kConfigSchemaVersion) + "\nsaved_by: \"OmniTune 0.1\"\n";
    std::vector<std::string> open;  // sections currently open
    auto indent = [&open] { return std::string(3 * open.size(), ' '); };
    for (const ConfigKey& k : configSchema()) {
        auto parts = splitConfigPath(k.path);
        const std::string leaf = parts.back();
        parts.pop_back();
        // The class list closes the colors section (it is a list, not a schema key).
        if (!open.empty() && open.front() == "colors" && parts.front() != "colors")
            out += writeColourClasses(config.colors.classes, std::string(3, ' '));
        std::size_t common = 0;
        while (common < open.size() && common < parts.size() && open[common] == parts[common]) ++common;
        open.resize(common);
        while (open.size() < parts.size()) {
            out += indent() + parts[open.size()] + ":\n";
            open.push_back(parts[open.size()]);
        }
        out += indent() + "# " + comment(k) + "\n" + indent() + leaf + ": " + valueText(k.get(config)) + "\n";
    }
    return out + "#  end marker: a saved file without it was cut short\ncomplete: 1\n";
}

std::optional<ConfigIssue> saveConfig(const Config& config, const std::string& path, bool keepBackup)
{
    const auto problems = checkConfig(config, path);
    if (!problems.empty()) return problems.front();
    auto writeError = [&](const std::string& file, const std::string& key, const std::string& message) {
        return ConfigIssue{ConfigIssueKind::WriteError, file, 0, key, message};
    };
    std::string maskPath;
    std::vector<std::uint8_t> png;
    if (!config.mask.empty()) {
        if (config.geometry.maskFile.empty())
            return ConfigIssue{ConfigIssueKind::MaskError, path, 0, "geometry.mask_file",
                               "the config holds a mask image but geometry.mask_file names no file for it"};
        maskPath = (std::filesystem::path(path).parent_path() / config.geometry.maskFile).string();
        if (!cv::imencode(".png", config.mask, png))
            return writeError(maskPath, "geometry.mask_file", "cannot encode the mask as PNG");
    }
    const FolderSaveLock lock(path);
    if (lock.error()) return writeError(path, "", *lock.error());
    // Both files are written and flushed before either replaces its old version, so a failure
    // (full disk, no permission) never leaves a new mask beside the old config.
    std::optional<StagedFile> mask;
    if (!maskPath.empty()) {
        mask.emplace(maskPath, std::string(png.begin(), png.end()));
        if (mask->error()) return writeError(maskPath, "geometry.mask_file", *mask->error());
    }
    StagedFile file(path, serializeConfig(config));
    if (file.error()) return writeError(path, "", *file.error());
    if (mask)
        if (auto err = mask->commit(keepBackup)) return writeError(maskPath, "geometry.mask_file", *err);
    if (auto err = file.commit(keepBackup)) return writeError(path, "", *err);
    return std::nullopt;
}

}  // namespace omnitune
