#include "core/ColorClass.h"

namespace omnitune {

std::string_view colorClassKey(ColorClass c)
{
    switch (c) {
    case ColorClass::Unknown: return "unknown";
    case ColorClass::Green: return "green";
    case ColorClass::White: return "white";
    case ColorClass::Black: return "black";
    case ColorClass::Orange: return "orange";
    case ColorClass::Cyan: return "cyan";
    case ColorClass::Magenta: return "magenta";
    }
    return "unknown";
}

std::array<std::uint8_t, 3> colorClassDisplayBgr(ColorClass c)
{
    switch (c) {
    case ColorClass::Unknown: return {128, 128, 128};
    case ColorClass::Green: return {0, 160, 0};
    case ColorClass::White: return {255, 255, 255};
    case ColorClass::Black: return {0, 0, 0};
    case ColorClass::Orange: return {0, 128, 255};
    case ColorClass::Cyan: return {255, 255, 0};
    case ColorClass::Magenta: return {255, 0, 255};
    }
    return {128, 128, 128};
}

}  // namespace omnitune
