#pragma once
// A top-level window that opens fully on its screen: the preferred size, shrunk to the screen's
// available area (less the taskbar and the window frame), centred on it. On a 1366x768 laptop
// the docks and the status bar then start on screen instead of below its edge.
#include <QRect>
#include <QSize>

class QWidget;

namespace omnitune {

// The window's geometry (without frame) for `available` (a screen's available geometry):
// `preferred` bounded by the area less `frame` (the decoration's extra width and height),
// centred in it.
QRect fitWindowGeometry(QSize preferred, QSize frame, const QRect& available);

// Applies fitWindowGeometry() on the screen the window is on (or the primary one). Before the
// window is shown its frame is unknown: a typical title bar and border are assumed.
void fitToScreen(QWidget* window, QSize preferred);

}  // namespace omnitune
