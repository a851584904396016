#pragma once
// Field-line pixels the colour classes miss. In dim or uneven light a line's grey falls below
// the line class's brightness (it reads as unknown or black), so the line arms of a junction of
// far lines go unseen and the junction passes as a ball. Such a pixel is still pale (little
// saturation) and clearly brighter than the carpet right beside the candidate.
#include "core/ColourClasses.h"
#include "core/FrameColour.h"

#include <cstdint>

namespace omnitune {

struct PaleLine {
    const FrameColour* frame = nullptr;  // null: no pale pixel (the line class alone)
    int maxSaturation = 0;               // 0..255
    double minValue = 0.0;               // 0..255: the ratio times the carpet's V near the candidate

    // Whether a pixel of class `id` at (x, y) is a pale line pixel: not the carpet's class, pale
    // and bright enough.
    bool at(int x, int y, std::uint8_t id, const ColourRoles& roles) const
    {
        if (!frame || roles.field(id)) return false;
        const Hsv c = frame->hsvAt(x, y);
        return c.s <= maxSaturation && c.v >= minValue;
    }
};

}  // namespace omnitune
