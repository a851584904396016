#include "core/ColourClasses.h"

#include <set>

namespace omnitune {

std::string_view colourRoleName(ColourRole role)
{
    switch (role) {
    case ColourRole::Field: return "field";
    case ColourRole::Line: return "line";
    case ColourRole::Black: return "black";
    case ColourRole::Ball: return "ball";
    case ColourRole::Marker: return "marker";
    case ColourRole::Other: return "other";
    }
    return "other";
}

std::optional<ColourRole> parseColourRole(std::string_view name)
{
    for (ColourRole r : kColourRoles)
        if (colourRoleName(r) == name) return r;
    return std::nullopt;
}

bool operator==(const ColourClassDef& a, const ColourClassDef& b)
{
    return a.name == b.name && a.role == b.role && a.display == b.display && a.enabled == b.enabled &&
           a.boxes == b.boxes;
}

ColourClasses defaultColourClasses()
{
    auto cls = [](const char* name, ColourRole role, std::array<std::uint8_t, 3> bgr, HsvRange box, bool on = true) {
        return ColourClassDef{name, role, bgr, on, {box}};
    };
    // Black and white first: their boxes ignore hue (black overlaps green's dark end).
    return {
        cls("black", ColourRole::Black, {0, 0, 0}, HsvRange{true, 0, 179, 0, 255, 0, 60}),
        cls("white", ColourRole::Line, {255, 255, 255}, HsvRange{true, 0, 179, 0, 50, 170, 255}),
        cls("green", ColourRole::Field, {0, 160, 0}, HsvRange{true, 35, 85, 60, 255, 40, 255}),
        cls("orange", ColourRole::Ball, {0, 128, 255}, HsvRange{true, 5, 22, 120, 255, 80, 255}),
        cls("cyan", ColourRole::Marker, {255, 255, 0}, HsvRange{true, 86, 105, 120, 255, 80, 255}),
        cls("magenta", ColourRole::Marker, {255, 0, 255}, HsvRange{true, 140, 170, 100, 255, 80, 255}),
        // Between orange's and green's hues; off so that the defaults classify as the thesis does.
        cls("yellow", ColourRole::Ball, {0, 220, 255}, HsvRange{true, 23, 34, 120, 255, 80, 255}, false),
    };
}

int findColourClass(const ColourClasses& classes, std::string_view name)
{
    for (std::size_t i = 0; i < classes.size(); ++i)
        if (classes[i].name == name) return int(i);
    return -1;
}

std::string colourClassName(const ColourClasses& classes, ColorClass id)
{
    const int i = int(id) - 1;
    return i >= 0 && i < int(classes.size()) ? classes[std::size_t(i)].name : std::string("unknown");
}

ColorClass classifyHsv(const ColourClasses& classes, int h, int s, int v)
{
    for (std::size_t i = 0; i < classes.size() && i < std::size_t(kMaxColourClasses); ++i)
        if (classes[i].contains(h, s, v)) return colourClassId(int(i));
    return ColorClass::Unknown;
}

bool isValidColourClassName(std::string_view name)
{
    if (name.empty() || name.size() > 32 || name == "unknown" || name == "none") return false;
    if (name[0] < 'a' || name[0] > 'z') return false;
    for (char c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
    return true;
}

std::vector<ConfigIssue> checkColourClasses(const ColourClasses& classes, const std::string& file)
{
    std::vector<ConfigIssue> out;
    auto fault = [&](ConfigIssueKind kind, const std::string& key, const std::string& message) {
        out.push_back(ConfigIssue{kind, file, 0, key, message});
    };
    if (classes.empty()) fault(ConfigIssueKind::Inconsistent, "colors.classes", "no colour class: at least a field class is needed");
    if (int(classes.size()) > kMaxColourClasses)
        fault(ConfigIssueKind::OutOfRange, "colors.classes",
              std::to_string(classes.size()) + " classes; at most " + std::to_string(kMaxColourClasses) +
                  " fit the segmented image's class ids");
    std::set<std::string> seen;
    bool field = false;
    for (std::size_t i = 0; i < classes.size(); ++i) {
        const ColourClassDef& c = classes[i];
        const std::string key = "colors.classes[" + std::to_string(i) + "]";
        if (!isValidColourClassName(c.name))
            fault(ConfigIssueKind::BadValue, key + ".name",
                  "\"" + c.name + "\" is no class name: use a-z first, then a-z, 0-9 or _ (at most 32; not unknown or none)");
        else if (!seen.insert(c.name).second)
            fault(ConfigIssueKind::DuplicateKey, key + ".name", "a second class named \"" + c.name + "\"");
        if (c.boxes.empty()) fault(ConfigIssueKind::Inconsistent, key + ".boxes", "class \"" + c.name + "\" has no HSV box");
        for (std::size_t j = 0; j < c.boxes.size(); ++j) {
            const HsvRange& b = c.boxes[j];
            const std::string bk = key + ".boxes[" + std::to_string(j) + "]";
            const std::string of = " (class \"" + c.name + "\")";
            auto outside = [](int x, int hi) { return x < 0 || x > hi; };
            if (outside(b.hMin, 179) || outside(b.hMax, 179))
                fault(ConfigIssueKind::OutOfRange, bk + ".h", "hue " + std::to_string(b.hMin) + ".." + std::to_string(b.hMax) + " is outside 0..179" + of);
            if (outside(b.sMin, 255) || outside(b.sMax, 255))
                fault(ConfigIssueKind::OutOfRange, bk + ".s", "saturation " + std::to_string(b.sMin) + ".." + std::to_string(b.sMax) + " is outside 0..255" + of);
            if (outside(b.vMin, 255) || outside(b.vMax, 255))
                fault(ConfigIssueKind::OutOfRange, bk + ".v", "value " + std::to_string(b.vMin) + ".." + std::to_string(b.vMax) + " is outside 0..255" + of);
            if (b.sMin > b.sMax)
                fault(ConfigIssueKind::Inconsistent, bk + ".s", "the box is empty: s min " + std::to_string(b.sMin) + " is above max " + std::to_string(b.sMax) + of);
            if (b.vMin > b.vMax)
                fault(ConfigIssueKind::Inconsistent, bk + ".v", "the box is empty: v min " + std::to_string(b.vMin) + " is above max " + std::to_string(b.vMax) + of);
        }
        field = field || (c.role == ColourRole::Field && c.enabled && !c.boxes.empty());
    }
    if (!classes.empty() && !field)
        fault(ConfigIssueKind::Inconsistent, "colors.classes",
              "no enabled class has role field: nothing would be carpet (the green / non-green image would be empty)");
    return out;
}

ColourRoles::ColourRoles(const ColourClasses& classes)
{
    for (std::size_t i = 0; i < classes.size() && i < std::size_t(kMaxColourClasses); ++i) {
        masks_[std::size_t(classes[i].role)] |= 1u << (i + 1);
        names_.push_back(classes[i].name);
    }
}

const ColourRoles& defaultColourRoles()
{
    static const ColourRoles roles;
    return roles;
}

ColorClass ColourRoles::idOf(std::string_view name) const
{
    for (std::size_t i = 0; i < names_.size(); ++i)
        if (names_[i] == name) return colourClassId(int(i));
    return ColorClass::Unknown;
}

}  // namespace omnitune
