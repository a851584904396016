#pragma once
// The workbench window's docks, all on the right as tabs of one stack with the thresholds in
// front: Thresholds, Legend (what the marks over the panes mean), Colours and Camera (the live
// camera's features, shown only while a camera is open). Panels used now and then (ball model,
// distance map, whole session) join the stack as a tab on first use: docked earlier, their size
// would squeeze the thresholds.
#include <QObject>

class QDockWidget;
class QMainWindow;
class QString;
class QWidget;

namespace omnitune {

class CameraPanel;
class ColourEditor;
class LiveController;
class ThresholdPanel;

class WindowDocks : public QObject {
    Q_OBJECT
public:
    WindowDocks(QMainWindow* window, ThresholdPanel* thresholds, ColourEditor* colours, CameraPanel* camera,
                LiveController* live);

    QDockWidget* thresholds() const { return thresholds_; }
    QDockWidget* colours() const { return colours_; }
    QDockWidget* camera() const { return camera_; }
    // Shows `panel` as a tab of the stack, in front; on its first use it is docked under
    // `title`, the dock named `objectName` (tests and saved layouts find it by that name).
    QDockWidget* show(QWidget* panel, const QString& title, const QString& objectName);

private:
    QDockWidget* add(QWidget* panel, const QString& title, const QString& objectName);

    QMainWindow* window_;
    QDockWidget* thresholds_ = nullptr;
    QDockWidget* colours_ = nullptr;
    QDockWidget* camera_ = nullptr;
};

}  // namespace omnitune
