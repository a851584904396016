#pragma once
// The workbench window's menu bar, in this order: File, Edit, View (panes, docks, overlay
// toggles), Playback, Camera, Colours, Session and Truth. Each action calls the window (through
// the callbacks) or the part it belongs to; the menus hold no state beyond the actions the window
// enables once a source is open and the recent-files list.
#include <QObject>

#include <functional>

class QAction;
class QMainWindow;

namespace omnitune {

class CameraSetup;
class ColourEditor;
class ConfigDocument;
class FrameNavigator;
class GeometryEditor;
class LiveController;
class PaneEditors;
class PipelineView;
class RecentFiles;
class TruthMarker;

// What the menus act on: the window's parts and what only the window can do.
struct WindowMenuTargets {
    ConfigDocument* doc;
    PipelineView* view;
    FrameNavigator* nav;
    LiveController* live;
    GeometryEditor* geometry;
    ColourEditor* colours;
    PaneEditors* paneEditors;
    CameraSetup* cameraSetup;
    TruthMarker* marker;
    std::function<void()> chooseSource;      // a session or image folder
    std::function<void()> chooseSourceFile;  // a video or an image
    std::function<void()> chooseConfig;
    std::function<void(const QString&)> openPath;  // a recent file
    std::function<void()> saveConfig;
    std::function<void()> saveConfigAs;
    std::function<void()> saveAsSession;
    std::function<void()> applyToSession;
    std::function<void(QWidget*)> showPanel;  // the distance map or ball model panel, docked
    QWidget* ballModel;
};

class WindowMenus : public QObject {
    Q_OBJECT
public:
    // Fills `window`'s menu bar; the docks named "thresholds" and "legend" must exist by then
    // (View toggles them).
    WindowMenus(QMainWindow* window, const WindowMenuTargets& targets);

    RecentFiles* recentFiles() const { return recent_; }
    // Disabled until a source is open (the window enables them).
    QAction* saveAsSession() const { return saveAsSession_; }
    QAction* setUpCamera() const { return setUpCamera_; }
    QAction* applyToSession() const { return applyToSession_; }

private:
    void addFile(QMainWindow* window, const WindowMenuTargets& t);
    void addEdit(QMainWindow* window, const WindowMenuTargets& t);
    void addView(QMainWindow* window, const WindowMenuTargets& t);
    void addPlayback(QMainWindow* window, const WindowMenuTargets& t);
    void addCameraAndColours(QMainWindow* window, const WindowMenuTargets& t);
    void addSession(QMainWindow* window, const WindowMenuTargets& t);

    RecentFiles* recent_ = nullptr;
    QAction* saveAsSession_ = nullptr;
    QAction* setUpCamera_ = nullptr;
    QAction* applyToSession_ = nullptr;
};

}  // namespace omnitune
