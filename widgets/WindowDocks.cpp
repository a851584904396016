#include "widgets/WindowDocks.h"

#include "widgets/CameraPanel.h"
#include "widgets/ColourEditor.h"
#include "widgets/LiveController.h"
#include "widgets/OverlayLegend.h"
#include "widgets/ThresholdPanel.h"

#include <QDockWidget>
#include <QMainWindow>

namespace omnitune {

WindowDocks::WindowDocks(QMainWindow* window, ThresholdPanel* thresholds, ColourEditor* colours, CameraPanel* camera,
                         LiveController* live)
    : QObject(window), window_(window)
{
    thresholds_ = add(thresholds, tr("Thresholds"), QStringLiteral("thresholds"));
    add(new OverlayLegend(window), tr("Legend"), QStringLiteral("legend"));  // "A3 98/100/96"
    colours_ = add(colours, tr("Colours"), QStringLiteral("colours"));       // classes and sampling (issue 10)
    camera_ = add(camera, tr("Camera"), QStringLiteral("camera"));
    // A tab saying "No camera" would only puzzle: the Camera tab is there while a camera is.
    camera_->hide();
    connect(live, &LiveController::cameraOpened, camera_, [this] {
        camera_->show();
        camera_->raise();
    });
    connect(live, &LiveController::cameraClosed, camera_, [this] {
        const bool inFront = !camera_->visibleRegion().isEmpty();
        camera_->hide();
        if (inFront) thresholds_->raise();  // not whichever tab happens to be next
    });
    thresholds_->raise();
}

QDockWidget* WindowDocks::add(QWidget* panel, const QString& title, const QString& objectName)
{
    auto* dock = new QDockWidget(title, window_);
    dock->setObjectName(objectName);
    dock->setWidget(panel);
    window_->addDockWidget(Qt::RightDockWidgetArea, dock);
    if (thresholds_) window_->tabifyDockWidget(thresholds_, dock);
    return dock;
}

QDockWidget* WindowDocks::show(QWidget* panel, const QString& title, const QString& objectName)
{
    auto* dock = qobject_cast<QDockWidget*>(panel->parentWidget());
    if (!dock) dock = add(panel, title, objectName);
    dock->show();
    dock->raise();
    return dock;
}

}  // namespace omnitune
