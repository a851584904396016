#include "widgets/OverlayLegend.h"

#include "widgets/CandidateLabel.h"
#include "widgets/Overlay.h"

#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QTextDocument>

namespace omnitune {

namespace {

enum class Swatch { Ring, DashedRing, DottedRing, ThickRing, Cross, Line, Fill, Move };

// The mark as the panes draw it, small.
QPixmap swatch(Swatch kind, const QColor& colour)
{
    QPixmap pixmap(28, 20);
    pixmap.fill(QColor(60, 90, 60));  // a carpet-like ground, as under the overlays
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing, true);
    const Qt::PenStyle style = kind == Swatch::DashedRing ? Qt::DashLine : kind == Swatch::DottedRing ? Qt::DotLine : Qt::SolidLine;
    p.setPen(QPen(colour, kind == Swatch::ThickRing ? 3 : 1.5, style));
    switch (kind) {
    case Swatch::Cross:
        p.drawLine(8, 10, 20, 10);
        p.drawLine(14, 4, 14, 16);
        break;
    case Swatch::Line: p.drawLine(3, 16, 25, 4); break;
    case Swatch::Move:  // as ImageView::paintMove draws it
        p.drawLine(2, 13, 8, 19);
        p.drawLine(2, 19, 8, 13);
        p.drawEllipse(QPointF(20, 8), 6, 6);
        p.setPen(QPen(colour, 1.5, Qt::DotLine));
        p.drawLine(QPointF(5, 16), QPointF(15.8, 12.2));
        break;
    case Swatch::Fill: p.fillRect(QRectF(4, 3, 20, 14), colour); break;
    default: p.drawEllipse(QPointF(14, 10), 7, 7); break;
    }
    return pixmap;
}

}  // namespace

OverlayLegend::OverlayLegend(QWidget* parent) : QWidget(parent)
{
    setObjectName("overlayLegend");
    struct Row {
        Swatch kind;
        QColor colour;
        QString text;
    };
    const Row rows[] = {
        {Swatch::Cross, overlay_colour::geometry(), tr("Robot centre; the yellow rings are the inner and outer mask radius")},
        {Swatch::Line, overlay_colour::maskOutline(), tr("Mask outline (pixels never processed)")},
        {Swatch::Fill, overlay_colour::maskTint(), tr("Masked: robot body, rods (never processed)")},
        {Swatch::DashedRing, overlay_colour::areas(), tr("Radial area bounds of the specific Hough (A1 innermost)")},
        {Swatch::Line, overlay_colour::sensors(), tr("Radial sensor rays (off by default, View menu)")},
        {Swatch::ThickRing, overlay_colour::accepted(), tr("Accepted ball, labelled with its field position in metres")},
        {Swatch::Ring, overlay_colour::accepted(), tr("Candidate that passed validation")},
        {Swatch::Ring, overlay_colour::rejected(), tr("Candidate rejected (hover it for the test it failed)")},
        {Swatch::Move, overlay_colour::rejected(), tr("Candidate moved by a second look: the cross is where the search put it "
                                                      "(its table row and tooltip say why)")},
        {Swatch::DashedRing, overlay_colour::truth(), tr("Ground truth marked for this frame (Truth menu)")},
        {Swatch::DottedRing, overlay_colour::cursor(), tr("Expected ball size under the cursor (ball model)")},
    };
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(6, 6, 6, 6);
    grid->setVerticalSpacing(3);
    int r = 0;
    for (const Row& row : rows) {
        auto* mark = new QLabel(this);
        mark->setPixmap(swatch(row.kind, row.colour));
        auto* text = new QLabel(row.text, this);
        text->setWordWrap(true);
        grid->addWidget(mark, r, 0, Qt::AlignTop);
        grid->addWidget(text, r, 1);
        ++r;
    }
    auto* labels = new QLabel(candidateLabelLegend(), this);
    labels->setObjectName("labelLegend");
    labels->setWordWrap(true);
    labels->setTextFormat(Qt::RichText);
    grid->addWidget(labels, r, 0, 1, 2);
    grid->setColumnStretch(1, 1);
    grid->setRowStretch(r + 1, 1);
}

QString OverlayLegend::text() const
{
    QStringList lines;
    for (const QLabel* label : findChildren<QLabel*>()) {
        if (label->text().isEmpty()) continue;
        QTextDocument doc;
        doc.setHtml(label->text());
        lines << doc.toPlainText();
    }
    return lines.join('\n');
}

}  // namespace omnitune
