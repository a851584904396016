#include "calib/colour/ColourProfile.h"

#include "core/AtomicFile.h"
#include "core/ColourClassesYaml.h"
#include "core/RegularFile.h"
#include "core/YamlText.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace omnitune {

namespace {

constexpr int kProfileFormat = 1;

}  // namespace

std::string colourProfileFolder(const std::string& configPath)
{
    return (std::filesystem::path(configPath).parent_path() / "colour-profiles").string();
}

std::optional<std::string> colourProfileFileName(const std::string& name)
{
    std::string out;
    bool dash = false;
    for (char c : name) {
        const char l = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
        if ((l >= 'a' && l <= 'z') || (l >= '0' && l <= '9') || l == '_') {
            if (dash && !out.empty()) out += '-';
            dash = false;
            out += l;
        } else {
            dash = true;
        }
    }
    if (out.empty()) return std::nullopt;
    return out.substr(0, 64) + ".yml";
}

std::string serializeColourProfile(const ColourProfile& p)
{
    std::string out = "%YAML:1.0\n---\n#  OmniTune colour profile (a venue's colour calibration). Reference: docs/config.md\n";
    out += "colour_profile: " + std::to_string(kProfileFormat) + "\n";
    out += "name: " + yamlQuoted(p.name) + "\n";
    out += "colors:\n";
    out += "   lut_bits: " + std::to_string(p.colors.bits) + "\n";
    out += "   black_relative: " + std::string(p.colors.blackRelative ? "1" : "0") + "\n";
    out += "   black_v_ratio: " + yamlNumber(p.colors.blackVRatio) + "\n";
    out += writeColourClasses(p.colors.classes, "   ");
    return out;
}

ColourProfileLoad parseColourProfile(const std::string& text, const std::string& fileName)
{
    ColourProfileLoad out;
    auto fail = [&](FileIssueKind kind, const std::string& key, const std::string& message) {
        out.error = FileIssue{kind, fileName, key.empty() ? 0 : yamlLineOfKey(text, key), key, message};
        return out;
    };
    cv::FileStorage fs;
    if (const auto err = openYamlText(text, fs)) {
        out.error = FileIssue{FileIssueKind::ParseError, fileName, err->line, "", "not a valid YAML profile: " + err->message};
        return out;
    }
    if (auto misread = checkWrittenValues(text, fs, fileName)) {
        out.error = misread;
        return out;
    }
    const cv::FileNode root = fs.root();
    if (!root.isMap() || root["colour_profile"].empty())
        return fail(FileIssueKind::NotAConfig, "colour_profile", "no 'colour_profile' key: this is not an OmniTune colour profile");
    if (!root["colour_profile"].isInt() || int(root["colour_profile"]) != kProfileFormat)
        return fail(FileIssueKind::UnknownFormat, "colour_profile",
                    "profile format " + yamlTypeOf(root["colour_profile"]) + " is not known to this build, which reads " +
                        std::to_string(kProfileFormat));
    if (!root["name"].isString()) return fail(FileIssueKind::WrongType, "name", "expected the profile's name as text, found " + yamlTypeOf(root["name"]));
    out.profile.name = std::string(root["name"]);
    const cv::FileNode colors = root["colors"];
    if (!colors.isMap()) return fail(FileIssueKind::WrongType, "colors", "expected the colors section, found " + yamlTypeOf(colors));
    ColorLutOptions& c = out.profile.colors;
    if (!colors["lut_bits"].empty()) {
        if (!colors["lut_bits"].isInt() || int(colors["lut_bits"]) < 4 || int(colors["lut_bits"]) > 8)
            return fail(FileIssueKind::OutOfRange, "colors.lut_bits", "expected an integer in 4..8");
        c.bits = int(colors["lut_bits"]);
    }
    if (!colors["black_relative"].empty()) {
        if (!colors["black_relative"].isInt() || (int(colors["black_relative"]) != 0 && int(colors["black_relative"]) != 1))
            return fail(FileIssueKind::WrongType, "colors.black_relative", "expected 0 or 1");
        c.blackRelative = int(colors["black_relative"]) == 1;
    }
    if (!colors["black_v_ratio"].empty()) {
        const cv::FileNode r = colors["black_v_ratio"];
        if (!(r.isReal() || r.isInt()) || !(double(r) >= 0.05 && double(r) <= 0.95))
            return fail(FileIssueKind::OutOfRange, "colors.black_v_ratio", "expected a number in 0.05..0.95");
        c.blackVRatio = double(r);
    }
    ColourClassesRead classes = readColourClasses(colors, text, fileName);
    if (classes.error) {
        out.error = classes.error;
        return out;
    }
    for (FileIssue& w : classes.warnings) out.warnings.push_back(std::move(w));
    c.classes = std::move(classes.classes);
    const auto problems = checkColourClasses(c.classes, fileName);
    if (!problems.empty()) out.error = problems.front();
    return out;
}

ColourProfileSave saveColourProfile(const std::string& folder, const ColourProfile& profile)
{
    ColourProfileSave out;
    const auto file = colourProfileFileName(profile.name);
    if (!file) {
        out.error = FileIssue{FileIssueKind::BadValue, folder, 0, "name",
                              "the profile name \"" + profile.name + "\" has no letter or digit to name its file by"};
        return out;
    }
    out.path = (std::filesystem::path(folder) / *file).string();
    if (const std::size_t at = findUnsavableCharacter(profile.name); at != std::string::npos || profile.name.size() > kMaxYamlTextBytes) {
        out.error = FileIssue{FileIssueKind::BadValue, out.path, 0, "name", "the profile name is too long or holds a control character"};
        return out;
    }
    const auto problems = checkColourClasses(profile.colors.classes, out.path);
    if (!problems.empty()) {
        out.error = problems.front();
        return out;
    }
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) {
        out.error = FileIssue{FileIssueKind::WriteError, folder, 0, "", "cannot create the folder: " + ec.message()};
        return out;
    }
    if (auto err = writeFileAtomically(out.path, serializeColourProfile(profile), false))
        out.error = FileIssue{FileIssueKind::WriteError, out.path, 0, "", *err};
    return out;
}

ColourProfileLoad loadColourProfile(const std::string& path)
{
    std::string why;
    const auto text = readRegularFile(path, kMaxYamlBytes, why);
    if (!text) {
        ColourProfileLoad out;
        out.error = FileIssue{FileIssueKind::FileUnreadable, path, 0, "", why};
        return out;
    }
    return parseColourProfile(*text, path);
}

std::vector<ColourProfileEntry> listColourProfiles(const std::string& folder)
{
    std::vector<ColourProfileEntry> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
        if (e.path().extension() != ".yml") continue;
        ColourProfileEntry entry;
        entry.path = e.path().string();
        const ColourProfileLoad load = loadColourProfile(entry.path);
        if (load.ok())
            entry.name = load.profile.name;
        else
            entry.error = load.error;
        out.push_back(std::move(entry));
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
    return out;
}

}  // namespace omnitune
