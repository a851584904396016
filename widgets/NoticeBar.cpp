#include "widgets/NoticeBar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>

namespace omnitune {

NoticeBar::NoticeBar(QWidget* parent) : QFrame(parent), label_(new QLabel(this)), buttons_(new QHBoxLayout)
{
    setObjectName("notice");
    setFrameShape(QFrame::StyledPanel);
    setStyleSheet("#notice { background: #fff4ce; } #notice QLabel { color: #4d3800; }");  // readable in any theme
    label_->setWordWrap(true);
    label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* close = new QToolButton(this);
    close->setIcon(style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    close->setAutoRaise(true);
    close->setToolTip(tr("Dismiss"));
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(6, 2, 2, 2);
    row->addWidget(label_, 1);
    row->addLayout(buttons_);
    row->addWidget(close, 0, Qt::AlignTop);
    connect(close, &QToolButton::clicked, this, &NoticeBar::clear);
    hide();
}

void NoticeBar::add(const QString& title, const QStringList& lines)
{
    if (lines.isEmpty()) return;
    // A config from an older version can miss dozens of keys: the panes keep their room.
    constexpr int kShown = 5;
    QStringList shown = lines.mid(0, kShown);
    if (lines.size() > kShown) shown << tr("... and %1 more").arg(lines.size() - kShown);
    entries_ << QStringLiteral("%1\n  %2").arg(title, shown.join(QStringLiteral("\n  ")));
    label_->setText(entries_.join('\n'));
    show();
}

void NoticeBar::addButton(QAction* action)
{
    auto* button = new QToolButton(this);
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    buttons_->addWidget(button, 0, Qt::AlignTop);
    show();
}

void NoticeBar::clear()
{
    while (QLayoutItem* item = buttons_->takeAt(0)) {
        item->widget()->hide();
        item->widget()->deleteLater();  // its own click may be what clears the bar
        delete item;
    }
    entries_.clear();
    label_->clear();
    hide();
}

QString NoticeBar::text() const { return label_->text(); }

}  // namespace omnitune
