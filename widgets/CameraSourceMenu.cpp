#include "widgets/CameraSourceMenu.h"

#include "calib/camera/CameraCatalog.h"

#include <QMenu>

namespace omnitune {

CameraSourceMenu::CameraSourceMenu(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu)
{
    connect(menu_, &QMenu::aboutToShow, this, &CameraSourceMenu::rebuild);
    rebuild();
}

void CameraSourceMenu::rebuild()
{
    menu_->clear();
    const CameraScan scan = listCameras();
    for (const CameraInfo& c : scan.cameras) {
        const QString source = QString::fromStdString(c.source);
        QAction* a = menu_->addAction(QStringLiteral("%1  (%2)").arg(QString::fromStdString(c.name), source),
                                      this, [this, source] { emit chosen(source, SimulatedStart::Good); });
        a->setObjectName("cameraSource:" + source);
    }
    // Why a backend found nothing (no FireWire bus, no /dev/video*): greyed out, for reading.
    for (const std::string& note : scan.notes) menu_->addAction(QString::fromStdString(note))->setEnabled(false);
    menu_->addSeparator();
    const std::pair<SimulatedStart, QString> starts[] = {
        {SimulatedStart::Good, tr("Simulated camera (the config's camera settings)")},
        {SimulatedStart::Dark, tr("Simulated camera, started dark")},
        {SimulatedStart::Bright, tr("Simulated camera, started bright (clipping)")},
        {SimulatedStart::Tinted, tr("Simulated camera, started tinted")}};
    for (const auto& [start, text] : starts) {
        QAction* a = menu_->addAction(text, this, [this, start = start] { emit chosen(QStringLiteral("simulated"), start); });
        const std::string_view name = simulatedStartName(start);
        const QString suffix = start == SimulatedStart::Good ? QString() : ":" + QString::fromUtf8(name.data(), int(name.size()));
        a->setObjectName("cameraSource:simulated" + suffix);
    }
}

}  // namespace omnitune
