#pragma once
// The colour classes of the segmentation. Ids are what the segmented image stores.
#include <array>
#include <cstdint>
#include <string_view>

namespace omnitune {

enum class ColorClass : std::uint8_t {
    Unknown = 0,  // no class matched (or pixel not processed)
    Green,        // field carpet
    White,        // field lines
    Black,        // obstacles (robots)
    Orange,       // the classic orange ball
    Cyan,         // team marker
    Magenta,      // team marker
};

inline constexpr int kColorClassCount = 7;

// Classes in the order the LUT tests them: the first range that contains a colour wins.
// Black and white come first because their ranges ignore hue.
inline constexpr std::array<ColorClass, 6> kClassificationOrder = {
    ColorClass::Black, ColorClass::White, ColorClass::Green,
    ColorClass::Orange, ColorClass::Cyan, ColorClass::Magenta};

// Lower-case key used in config.yml ("green", "white", ...).
std::string_view colorClassKey(ColorClass c);

// BGR false colour used for the segmented stage image.
std::array<std::uint8_t, 3> colorClassDisplayBgr(ColorClass c);

}  // namespace omnitune
