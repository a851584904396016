#pragma once
// Venue profiles: a colour calibration (the colors section of a config: classes, LUT bits,
// relative black) saved under a name ("home lab", "venue field A"), one small YAML file per
// profile in a folder beside the config (colour-profiles/NAME.yml), so a team switches between
// venues without retuning. Files are written atomically; the parser is pure (text in, profile
// plus typed issues out).
//
//   %YAML:1.0
//   ---
//   colour_profile: 1
//   name: "venue field A"
//   colors:
//      lut_bits: 6
//      black_relative: 1
//      black_v_ratio: 0.45
//      classes: ...            (as in config.yml, core/ColourClassesYaml.h)
#include "core/ColorLut.h"
#include "core/FileIssue.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct ColourProfile {
    std::string name;        // as the user typed it; the file name is derived from it
    ColorLutOptions colors;  // the calibration
};

struct ColourProfileLoad {
    ColourProfile profile;
    std::vector<FileIssue> warnings;
    std::optional<FileIssue> error;
    bool ok() const { return !error.has_value(); }
};

// The folder of the profiles of the config at `configPath`: CONFIG_DIR/colour-profiles.
std::string colourProfileFolder(const std::string& configPath);
// "Venue field A" -> "venue-field-a.yml": lower case, runs of other characters as one '-';
// nothing when no letter or digit is left.
std::optional<std::string> colourProfileFileName(const std::string& name);

std::string serializeColourProfile(const ColourProfile& profile);
ColourProfileLoad parseColourProfile(const std::string& text, const std::string& fileName);

// Writes folder/FILE atomically (creating the folder); the profile's classes are checked first
// and nothing is written when they are invalid. Returns the path written or the fault.
struct ColourProfileSave {
    std::string path;
    std::optional<FileIssue> error;
};
ColourProfileSave saveColourProfile(const std::string& folder, const ColourProfile& profile);
ColourProfileLoad loadColourProfile(const std::string& path);

// The profiles in `folder` by name (files that do not load are listed with their error).
struct ColourProfileEntry {
    std::string path;
    std::string name;                // empty when the file does not load
    std::optional<FileIssue> error;
};
std::vector<ColourProfileEntry> listColourProfiles(const std::string& folder);

}  // namespace omnitune
