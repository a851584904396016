#pragma once
// Field-line pixels the colour classes miss. In dim or uneven light a line's grey falls below
// the line class's brightness (it reads as unknown or black), so the line arms of a junction of
// far lines go unseen and the junction passes as a ball. Such a pixel is still pale (little
// saturation) and clearly brighter than the carpet right beside the candidate. Dimmer still, a
// far line is barely brighter than the carpet and falls in the carpet's own class; such a pixel
// counts when it is pale, a little brighter than the carpet and not the carpet's own colour.
#include "core/CarpetColour.h"
#include "core/ColourClasses.h"
#include "core/FrameColour.h"

#include <cstdint>

namespace omnitune {

struct PaleLine {
    const FrameColour* frame = nullptr;  // null: no pale pixel (the line class alone)
    int maxSaturation = 0;               // 0..255
    double minValue = 0.0;               // 0..255: the ratio times the carpet's V near the candidate
    // 0..255: the least V of a pale pixel of the carpet's class (pale_line_carpet_value_ratio x
    // the carpet's V); negative: such a pixel is never line.
    double carpetClassMinValue = -1.0;
    CarpetColour carpet;                 // the carpet's own colour around the candidate
    CarpetTolerance tolerance;           // how far from it a pixel is still carpet

    // Whether a pixel of class `id` at (x, y) is a pale line pixel: pale and bright enough, and
    // when of the carpet's class, not of the carpet's colour.
    bool at(int x, int y, std::uint8_t id, const ColourRoles& roles) const
    {
        if (!frame) return false;
        const bool carpetClass = roles.field(id);
        if (carpetClass && carpetClassMinValue < 0.0) return false;
        const Hsv c = frame->hsvAt(x, y);
        if (c.s > maxSaturation || c.v < (carpetClass ? carpetClassMinValue : minValue)) return false;
        return !carpetClass || !carpet.matches(c, tolerance);
    }
};

}  // namespace omnitune
