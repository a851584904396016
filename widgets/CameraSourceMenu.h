#pragma once
// Camera > Source: the cameras CameraCatalog finds (IIDC cameras by GUID, V4L2 devices), looked
// for again each time the menu opens (a camera plugged in meanwhile shows up), and the
// simulated camera with the config's settings or started badly set (dark, bright, tinted) to
// try the automatic calibration. Choosing one says which; opening it is the window's job.
// Action object names: "cameraSource:SOURCE" ("cameraSource:simulated",
// "cameraSource:simulated:dark", "cameraSource:v4l2:/dev/video0").
#include "calib/camera/SimulatedCamera.h"

#include <QObject>
#include <QString>

class QMenu;

namespace omnitune {

class CameraSourceMenu : public QObject {
    Q_OBJECT
public:
    // Fills `menu` now and whenever it is about to show.
    explicit CameraSourceMenu(QMenu* menu, QObject* parent = nullptr);

    void rebuild();

signals:
    // `source` as CameraCatalog's openCamera() takes it; `start` only for "simulated".
    void chosen(const QString& source, omnitune::SimulatedStart start);

private:
    QMenu* menu_;
};

}  // namespace omnitune
