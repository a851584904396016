#include "widgets/ColourSwatch.h"

#include <QPainter>
#include <QPixmap>

namespace omnitune {

QIcon colourSwatch(const QColor& colour)
{
    QPixmap p(14, 14);
    p.fill(colour);
    QPainter painter(&p);
    painter.setPen(Qt::black);
    painter.drawRect(0, 0, 13, 13);
    return QIcon(p);
}

}  // namespace omnitune
