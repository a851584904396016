#pragma once
// Small shared pieces of the Colours tab: a class's display colour as a Qt colour and as a
// framed square icon for the lists, and the tab's push buttons (named for tests, with a tip).
#include <QColor>
#include <QIcon>

class QPushButton;
class QWidget;

#include <array>
#include <cstdint>

namespace omnitune {

// A class's display colour (BGR, as the segmented image stores it) as a Qt colour.
inline QColor toQColor(const std::array<std::uint8_t, 3>& bgr) { return QColor(bgr[2], bgr[1], bgr[0]); }

// A 14 px square of `colour` with a black frame (a white class stays visible on white).
QIcon colourSwatch(const QColor& colour);

// A push button with `text`, tooltip `tip` and object name `name`.
QPushButton* colourTabButton(const QString& text, const QString& tip, const QString& name, QWidget* parent);

}  // namespace omnitune
