#pragma once
// A part's one-line messages ("saved", "refused: ...") shown on the window's status bar for a
// while: the window forwards every part's `message` signal the same way.
#include <QMainWindow>
#include <QStatusBar>
#include <QString>

namespace omnitune {

constexpr int kShortMessageMs = 5000;  // a file opened or saved, a geometry nudge
constexpr int kMessageMs = 8000;       // a refusal or a result worth reading

template <typename Sender, typename Signal>
void showMessagesOnStatusBar(QMainWindow* window, const Sender* sender, Signal signal, int ms = kMessageMs)
{
    QObject::connect(sender, signal, window, [window, ms](const QString& m) { window->statusBar()->showMessage(m, ms); });
}

}  // namespace omnitune
