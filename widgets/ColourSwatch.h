#pragma once
// Small pictures of a colour class for the Colours tab's lists: its display colour as a Qt
// colour and as a framed square icon.
#include <QColor>
#include <QIcon>

#include <array>
#include <cstdint>

namespace omnitune {

// A class's display colour (BGR, as the segmented image stores it) as a Qt colour.
inline QColor toQColor(const std::array<std::uint8_t, 3>& bgr) { return QColor(bgr[2], bgr[1], bgr[0]); }

// A 14 px square of `colour` with a black frame (a white class stays visible on white).
QIcon colourSwatch(const QColor& colour);

}  // namespace omnitune
