#include "widgets/PaneSketch.h"

#include "widgets/ImageView.h"

#include <QEvent>
#include <QPainter>

namespace omnitune {

PaneSketch::PaneSketch(ImageView* pane, Paint paint) : QWidget(pane), pane_(pane), paint_(std::move(paint))
{
    setAttribute(Qt::WA_TransparentForMouseEvents);  // presses, drags and the wheel go to the pane
    setAttribute(Qt::WA_NoSystemBackground);
    setObjectName(QStringLiteral("paneSketch"));
    setGeometry(pane->rect());
    pane->installEventFilter(this);
    hide();
}

bool PaneSketch::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == pane_ && event->type() == QEvent::Resize) setGeometry(pane_->rect());
    return QWidget::eventFilter(watched, event);
}

void PaneSketch::paintEvent(QPaintEvent*)
{
    if (pane_->image().isNull()) return;
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, true);
    paint_(p, *pane_);
}

}  // namespace omnitune
