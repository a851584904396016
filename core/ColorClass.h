#pragma once
// A colour class id, as the segmented image stores it: 0 is no class, 1..N the classes of
// colors.classes in their list order (core/ColourClasses.h, at most 15). The named values are
// the ids of the default classes, for tests and for code that speaks of the thesis' classes;
// the detector itself asks a class's role (ColourRoles), never its id or name.
#include <cstdint>

namespace omnitune {

enum class ColorClass : std::uint8_t {
    Unknown = 0,  // no class matched (or pixel not processed)
    Black,        // obstacles (robots)
    White,        // field lines
    Green,        // field carpet
    Orange,       // the classic orange ball
    Cyan,         // team marker
    Magenta,      // team marker
    Yellow,       // a yellow ball (off by default)
};

}  // namespace omnitune
