#pragma once
// Numbers in the fits' messages: fixed decimals, no locale.
#include <cstdio>
#include <string>

namespace omnitune {

inline std::string fixedText(double value, int decimals = 1)
{
    char b[48];
    std::snprintf(b, sizeof b, "%.*f", decimals, value);
    return b;
}

}  // namespace omnitune
