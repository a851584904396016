#include "widgets/ScreenFit.h"

#include <QGuiApplication>
#include <QScreen>
#include <QWidget>

#include <algorithm>

namespace omnitune {

QRect fitWindowGeometry(QSize preferred, QSize frame, const QRect& available)
{
    const QSize room = available.size() - frame;
    const QSize size(std::max(1, std::min(preferred.width(), room.width())),
                     std::max(1, std::min(preferred.height(), room.height())));
    // The frame with its decoration, centred; the borders are even, the rest is the title bar.
    QRect outer(QPoint(0, 0), size + frame);
    outer.moveCenter(available.center());
    outer.moveTopLeft(QPoint(std::max(outer.left(), available.left()), std::max(outer.top(), available.top())));
    const int border = frame.width() / 2;
    return QRect(outer.topLeft() + QPoint(border, frame.height() - border), size);
}

void fitToScreen(QWidget* window, QSize preferred)
{
    QScreen* screen = window->screen() ? window->screen() : QGuiApplication::primaryScreen();
    if (!screen) {
        window->resize(preferred);
        return;
    }
    // Shown: the real frame. Not yet: about a title bar and thin borders.
    const QSize frame = window->isVisible() ? window->frameGeometry().size() - window->geometry().size() : QSize(8, 38);
    window->setGeometry(fitWindowGeometry(preferred, frame, screen->availableGeometry()));
}

}  // namespace omnitune
