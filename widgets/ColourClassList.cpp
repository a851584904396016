#include "widgets/ColourClassList.h"

#include "widgets/ColourSwatch.h"

#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace omnitune {

QString colourSharePct(double pct) { return QString::number(pct, 'f', pct > 0 && pct < 1 ? 2 : 1) + QStringLiteral(" %"); }

ColourClassList::ColourClassList(QWidget* parent)
    : QGroupBox(tr("Classes (first in the list wins)"), parent), list_(new QListWidget)
{
    auto* cl = new QVBoxLayout(this);
    list_->setObjectName("classList");
    list_->setToolTip(tr("A pixel gets the first class whose boxes hold its colour; the tick switches a class "
                         "on or off; the percentage is its share of the processed pixels of the frame on screen"));
    cl->addWidget(list_);
    auto* row = new QHBoxLayout;
    QPushButton* add = colourTabButton(tr("Add"), tr("A new class at the end of the list; sample into it"), "addClass", this);
    QPushButton* remove = colourTabButton(tr("Remove"), tr("Remove the selected class"), "removeClass", this);
    QPushButton* up = colourTabButton(tr("Up"), tr("Higher priority: wins pixels it shares with the class above"), "classUp", this);
    QPushButton* down = colourTabButton(tr("Down"), tr("Lower priority"), "classDown", this);
    for (QPushButton* b : {add, remove, up, down}) row->addWidget(b);
    cl->addLayout(row);
    QPushButton* autoButton = colourTabButton(tr("Auto colours from this frame"),
                                     tr("First guess: the dominant hue of the processed area is the carpet; black "
                                        "and white relative to its brightness; one undo step"),
                                     "autoColours", this);
    cl->addWidget(autoButton);

    connect(add, &QPushButton::clicked, this, &ColourClassList::addRequested);
    connect(remove, &QPushButton::clicked, this, &ColourClassList::removeRequested);
    connect(up, &QPushButton::clicked, this, [this] { emit moveRequested(-1); });
    connect(down, &QPushButton::clicked, this, [this] { emit moveRequested(1); });
    connect(autoButton, &QPushButton::clicked, this, &ColourClassList::autoRequested);
    connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0) emit currentChanged(row);
    });
    connect(list_, &QListWidget::itemChanged, this,
            [this](QListWidgetItem* item) { emit enabledChanged(list_->row(item), item->checkState() == Qt::Checked); });
}

void ColourClassList::setClasses(const ColourClasses& classes, int current)
{
    const QSignalBlocker block(list_);
    list_->clear();
    for (const ColourClassDef& def : classes) {
        auto* item = new QListWidgetItem(colourSwatch(toQColor(def.display)), QString(), list_);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(def.enabled ? Qt::Checked : Qt::Unchecked);
    }
    list_->setCurrentRow(current);
    // Every class in view without scrolling (at most 15): the tab scrolls instead.
    if (list_->count() > 0)
        list_->setMinimumHeight(list_->count() * std::max(list_->sizeHintForRow(0), fontMetrics().height() + 5) +
                                2 * list_->frameWidth());
}

void ColourClassList::setShares(const ColourClasses& classes, const ClassShares* shares)
{
    const QSignalBlocker block(list_);
    for (int i = 0; i < list_->count() && i < int(classes.size()); ++i) {
        const ColourClassDef& def = classes[std::size_t(i)];
        QString text = QStringLiteral("%1  ·  %2").arg(QString::fromStdString(def.name),
                                                      QString::fromUtf8(colourRoleName(def.role).data()));
        if (shares) text += QStringLiteral("  ·  ") + colourSharePct(shares->pct(shares->counts[std::size_t(i)]));
        list_->item(i)->setText(text);
    }
}

}  // namespace omnitune
