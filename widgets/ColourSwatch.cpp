#include "widgets/ColourSwatch.h"

#include <QPainter>
#include <QPushButton>
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

QPushButton* colourTabButton(const QString& text, const QString& tip, const QString& name, QWidget* parent)
{
    auto* b = new QPushButton(text, parent);
    b->setToolTip(tip);
    b->setObjectName(name);
    return b;
}

}  // namespace omnitune
