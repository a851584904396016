#pragma once
// The colour classes of the segmentation as data (colors.classes in config.yml): each class has
// a name, a display colour, a role and one or more HSV boxes. A pixel takes the first class in
// list order (the priority) with a box that holds its colour. What the detector does with a
// class follows from its role, never from its name: the carpet is every class with role field
// (a cyan-green and a dark-green region may both be), black every class with role black.
//
// The segmented image stores a class's position in the list plus one (ColorClass, 0 = no
// class); the LUT keeps ids in 4 bits, hence at most kMaxColourClasses classes.
#include "core/ColorClass.h"
#include "core/ConfigIssue.h"
#include "core/HsvRange.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace omnitune {

inline constexpr int kMaxColourClasses = 15;

// What the detector uses a class for.
enum class ColourRole : std::uint8_t {
    Field,   // the carpet: white in the green / non-green image, "green" for validation
    Line,    // field lines: edges.white_level in the binary image
    Black,   // robots and shadows: the non-black test; relative black makes pixels this class
    Ball,    // a ball colour (validation.ball_hint_class may name one)
    Marker,  // team markers
    Other,   // shown in the segmented pane, no meaning to the detector
};
inline constexpr std::array<ColourRole, 6> kColourRoles = {ColourRole::Field, ColourRole::Line,  ColourRole::Black,
                                                           ColourRole::Ball,  ColourRole::Marker, ColourRole::Other};
// "field", "line", "black", "ball", "marker", "other": the config's words.
std::string_view colourRoleName(ColourRole role);
std::optional<ColourRole> parseColourRole(std::string_view name);

struct ColourClassDef {
    std::string name;                                     // unique key: a-z first, then a-z, 0-9, '_'
    ColourRole role = ColourRole::Other;
    std::array<std::uint8_t, 3> display{128, 128, 128};  // BGR of the segmented pane
    bool enabled = true;                                  // a disabled class never matches
    std::vector<HsvRange> boxes;                          // the class is their union

    bool contains(int h, int s, int v) const
    {
        if (!enabled) return false;
        for (const HsvRange& b : boxes)
            if (b.contains(h, s, v)) return true;
        return false;
    }
};
bool operator==(const ColourClassDef& a, const ColourClassDef& b);
inline bool operator!=(const ColourClassDef& a, const ColourClassDef& b) { return !(a == b); }

using ColourClasses = std::vector<ColourClassDef>;

// The thesis' six classes with its ranges, in the order black, white, green, orange, cyan,
// magenta (their ids are ColorClass's named values), then yellow, a ball class that is off so
// that the default segmentation stays the thesis' one.
ColourClasses defaultColourClasses();

// Id of the class at list position `index` (0-based).
inline ColorClass colourClassId(int index) { return static_cast<ColorClass>(index + 1); }
// List position of the class named `name`, or -1.
int findColourClass(const ColourClasses& classes, std::string_view name);
// The name of class `id`, "unknown" for 0 or an id beyond the list.
std::string colourClassName(const ColourClasses& classes, ColorClass id);

// Direct classification of one HSV triple (OpenCV's 8-bit scale): the first class in list order
// with a box that holds it, Unknown when none does.
ColorClass classifyHsv(const ColourClasses& classes, int h, int s, int v);

// Whether `name` may name a class: non-empty, at most 32 characters, a-z first, then a-z, 0-9
// and '_'; "unknown" and "none" are taken (no class, no ball hint).
bool isValidColourClassName(std::string_view name);

// Every fault of a class list, each with its key ("colors.classes[2].boxes[0]") and what is
// wrong: no class or more than kMaxColourClasses, a bad or duplicate name, a class with no box,
// a box with a bound outside its scale or min above max on S or V (hue min above max wraps and
// is allowed), and no enabled field class (nothing would be carpet).
std::vector<ConfigIssue> checkColourClasses(const ColourClasses& classes, const std::string& file = {});

// What each class id of a segmented image is for: a per-pixel lookup for the detector's stages.
class ColourRoles {
public:
    ColourRoles() : ColourRoles(defaultColourClasses()) {}
    explicit ColourRoles(const ColourClasses& classes);

    bool is(std::uint8_t id, ColourRole role) const { return id < 32 && ((masks_[std::size_t(role)] >> id) & 1u); }
    bool field(std::uint8_t id) const { return is(id, ColourRole::Field); }
    bool black(std::uint8_t id) const { return is(id, ColourRole::Black); }
    bool line(std::uint8_t id) const { return is(id, ColourRole::Line); }
    bool marker(std::uint8_t id) const { return is(id, ColourRole::Marker); }
    // The class named `name` (Unknown: none, or "none").
    ColorClass idOf(std::string_view name) const;

private:
    std::array<std::uint32_t, kColourRoles.size()> masks_{};  // bit `id` set: class id has the role
    std::vector<std::string> names_;
};

// The roles of the default classes (one shared instance).
const ColourRoles& defaultColourRoles();

}  // namespace omnitune
