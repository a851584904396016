#pragma once
// colors.classes in config.yml: reading (a pure parser on the `colors` section, with typed
// issues), writing, and its part of docs/config.md. The form:
//
//   colors:
//      classes:
//         - name: "green"            # unique: a-z first, then a-z, 0-9, _
//           role: field              # field | line | black | ball | marker | other
//           display: [ 0, 160, 0 ]   # BGR in the segmented pane
//           enabled: 1               # optional, default 1
//           boxes:                   # at least one; the class is their union
//              - { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] }
//
// Configs written before the list (colors.black.h_min, colors.green.v_max, ...) are read as
// before, in the old order with the old classes' roles, with an OldForm warning.
#include "core/ColourClasses.h"
#include "core/ConfigIssue.h"

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct ColourClassesRead {
    ColourClasses classes = defaultColourClasses();
    std::vector<ConfigIssue> warnings;  // missing list (defaults used), unknown keys, the old form
    std::optional<ConfigIssue> error;   // the first fault (a wrong type, an unknown role, ...)
    bool oldForm = false;               // read from the old per-class keys
};

// `colors`: the config's colors section (may be empty); `text` only gives messages their line.
ColourClassesRead readColourClasses(const cv::FileNode& colors, const std::string& text, const std::string& fileName);

// Whether the dotted `path` belongs to the class list ("colors.classes") or, with `oldForm`, to
// the old per-class sections ("colors.green"): the parser's unknown-key scan leaves them alone.
bool isColourClassesPath(const std::string& path, bool oldForm);

// The `classes:` block at `indent` (the colors section's own indent), ending in a newline.
std::string writeColourClasses(const ColourClasses& classes, const std::string& indent);

// docs/config.md's description of the list with the default classes.
std::string colourClassesMarkdown();

}  // namespace omnitune
