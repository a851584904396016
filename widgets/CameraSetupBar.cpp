#include "widgets/CameraSetupBar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QToolButton>

namespace omnitune {

CameraSetupBar::CameraSetupBar(QWidget* parent)
    : QFrame(parent), label_(new QLabel(this)), adapt_(new QPushButton(tr("Adapt the config to these frames"), this)),
      setUp_(new QPushButton(tr("Set up this camera"), this))
{
    setObjectName("cameraSetup");
    setFrameShape(QFrame::StyledPanel);
    // The notice strip's colours, a shade stronger: this one asks for an action.
    setStyleSheet("#cameraSetup { background: #ffe79a; } #cameraSetup QLabel { color: #4d3800; }");
    label_->setWordWrap(true);
    label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    adapt_->setToolTip(tr("Centre the mirror in the frame as the largest circle that fits, and scale every radius of "
                          "the config (areas, sensors, distance map, ball model) to it: the panes show this camera at once"));
    setUp_->setToolTip(tr("Find the mirror centre and rim and the robot body in a few frames of this source, then propose "
                          "a mask of what stays put while the field moves; each step is one Ctrl+Z"));
    auto* close = new QToolButton(this);
    close->setIcon(style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    close->setAutoRaise(true);
    close->setToolTip(tr("Dismiss"));
    for (QWidget* w : {static_cast<QWidget*>(adapt_), static_cast<QWidget*>(setUp_), static_cast<QWidget*>(close)})
        w->setFocusPolicy(Qt::NoFocus);  // the frames keep the keyboard (arrow keys step)
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(6, 2, 2, 2);
    row->addWidget(label_, 1);
    row->addWidget(adapt_, 0, Qt::AlignVCenter);
    row->addWidget(setUp_, 0, Qt::AlignVCenter);
    row->addWidget(close, 0, Qt::AlignTop);
    connect(adapt_, &QPushButton::clicked, this, &CameraSetupBar::adaptRequested);
    connect(setUp_, &QPushButton::clicked, this, &CameraSetupBar::setUpRequested);
    connect(close, &QToolButton::clicked, this, &QWidget::hide);
    hide();
}

void CameraSetupBar::showMessage(const QString& text, bool offerAdapt, bool offerSetUp)
{
    label_->setText(text);
    adapt_->setVisible(offerAdapt);
    setUp_->setVisible(offerSetUp);
    show();
}

QString CameraSetupBar::text() const { return label_->text(); }

}  // namespace omnitune
