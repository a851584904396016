#include "widgets/WindowMenus.h"

#include "widgets/CameraSetup.h"
#include "widgets/ColourEditor.h"
#include "widgets/ConfigDocument.h"
#include "widgets/DistancePointsPanel.h"
#include "widgets/FrameNavigator.h"
#include "widgets/GeometryEditor.h"
#include "widgets/LiveController.h"
#include "widgets/PaneEditors.h"
#include "widgets/PipelineView.h"
#include "widgets/RecentFiles.h"
#include "widgets/TruthMarker.h"

#include <QAction>
#include <QDockWidget>
#include <QIcon>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QUndoStack>

#include <utility>

namespace omnitune {

WindowMenus::WindowMenus(QMainWindow* window, const WindowMenuTargets& targets) : QObject(window)
{
    addFile(window, targets);
    addEdit(window, targets);
    addView(window, targets);
    addPlayback(window, targets);
    addCameraAndColours(window, targets);
    addSession(window, targets);
    targets.marker->fillMenu(window->menuBar()->addMenu(tr("&Truth")));
}

void WindowMenus::addFile(QMainWindow* window, const WindowMenuTargets& t)
{
    QMenu* file = window->menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open session or image folder..."), window, t.chooseSource, QKeySequence::Open);
    file->addAction(tr("Open &video or image file..."), window, t.chooseSourceFile);
    file->addAction(tr("Open &config..."), window, t.chooseConfig);
    recent_ = new RecentFiles(QStringLiteral("recentFiles"), file->addMenu(tr("Open &recent")), window);
    connect(recent_, &RecentFiles::chosen, window, t.openPath);
    file->addSeparator();
    file->addAction(tr("&Save config"), window, t.saveConfig, QKeySequence::Save);
    file->addAction(tr("Save config &as..."), window, t.saveConfigAs, QKeySequence::SaveAs);
    // An image folder or video becomes a session folder, so it can be marked and evaluated.
    saveAsSession_ = file->addAction(tr("Save as sessio&n..."), window, t.saveAsSession);
    saveAsSession_->setObjectName("saveAsSession");
    saveAsSession_->setStatusTip(tr("Copy the open image folder or video into a session folder (frames, config, truth.csv) and open it"));
    saveAsSession_->setEnabled(false);  // until a source is open
    ConfigDocument* doc = t.doc;
    file->addAction(tr("&Revert to saved"), window, [window, doc] {
        if (const auto err = doc->revert()) QMessageBox::warning(window, tr("Revert"), *err);
    });
    file->addSeparator();
    file->addAction(tr("&Quit"), window, &QWidget::close, QKeySequence::Quit);
}

void WindowMenus::addEdit(QMainWindow* window, const WindowMenuTargets& t)
{
    QMenu* edit = window->menuBar()->addMenu(tr("&Edit"));
    QAction* undo = t.doc->undoStack()->createUndoAction(window, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = t.doc->undoStack()->createRedoAction(window, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
}

void WindowMenus::addView(QMainWindow* window, const WindowMenuTargets& t)
{
    QMenu* view = window->menuBar()->addMenu(tr("&View"));
    PipelineView* panes = t.view;
    ConfigDocument* doc = t.doc;
    view->addAction(tr("&Fit all panes"), panes->transform(), &ViewTransform::fit, QKeySequence(Qt::Key_F));
    view->addAction(tr("&1:1"), window, [panes, doc] {
        const auto c = panes->transform()->isFit() ? QPointF(doc->config().geometry.imageWidth / 2.0,
                                                              doc->config().geometry.imageHeight / 2.0)
                                                    : panes->transform()->center();
        panes->transform()->setZoom(1.0, c);
    }, QKeySequence(Qt::Key_1));
    if (auto* dock = window->findChild<QDockWidget*>("thresholds")) {
        QAction* panel = dock->toggleViewAction();  // a closed panel comes back from here
        panel->setText(tr("&Thresholds panel"));
        view->addAction(panel);
    }
    if (auto* dock = window->findChild<QDockWidget*>("legend")) {
        QAction* legend = dock->toggleViewAction();
        legend->setText(tr("Overlay &legend"));
        legend->setIcon(QIcon(":/icons/legend.png"));
        view->addAction(legend);
    }
    view->addSeparator();
    OverlayOptions& o = panes->overlays();
    const std::pair<QString, bool*> toggles[] = {
        {tr("Robot centre, mask radii and mask outline"), &o.geometry}, {tr("Radial areas"), &o.areas},
        {tr("Radial sensors"), &o.sensors},               {tr("Candidates with scores"), &o.candidates},
        {tr("Accepted ball"), &o.ball},                    {tr("Expected ball under the cursor"), &o.cursorRadius},
        {tr("Ground truth"), &o.truth}};
    for (const auto& [name, flag] : toggles) {
        QAction* a = view->addAction(name);
        a->setCheckable(true);
        a->setChecked(*flag);
        connect(a, &QAction::toggled, window, [panes, flag = flag](bool on) {
            *flag = on;
            for (int i = 0; i < PipelineView::kPaneCount; ++i) panes->pane(i)->update();
        });
    }
}

void WindowMenus::addPlayback(QMainWindow* window, const WindowMenuTargets& t)
{
    // Playback keys work anywhere in the window but in text fields.
    const std::pair<QKeySequence, void (FrameNavigator::*)()> keys[] = {
        {Qt::Key_Space, &FrameNavigator::togglePlay}, {Qt::Key_Right, &FrameNavigator::next},
        {Qt::Key_Left, &FrameNavigator::previous},    {Qt::Key_Home, &FrameNavigator::first},
        {Qt::Key_End, &FrameNavigator::last}};
    QMenu* play = window->menuBar()->addMenu(tr("&Playback"));
    const QString names[] = {tr("Play / pause"), tr("Next frame"), tr("Previous frame"), tr("First frame"), tr("Last frame")};
    for (int i = 0; i < 5; ++i) {
        QAction* a = play->addAction(names[i], t.nav, keys[i].second);
        a->setShortcut(keys[i].first);
    }
}

void WindowMenus::addCameraAndColours(QMainWindow* window, const WindowMenuTargets& t)
{
    QMenu* camera = window->menuBar()->addMenu(tr("&Camera"));
    t.live->fillMenu(camera);
    camera->addSeparator();
    t.geometry->fillMenu(camera);
    t.colours->fillMenu(window->menuBar()->addMenu(tr("C&olours")));  // beside Camera on the bar
    t.paneEditors->fillMenu(camera);
    const auto showPanel = t.showPanel;
    PaneEditors* paneEditors = t.paneEditors;
    camera->addAction(tr("&Distance map points and fit..."), window, [showPanel, paneEditors] { showPanel(paneEditors->distances()); })
        ->setObjectName("distanceMapPoints");
    QWidget* ballModel = t.ballModel;
    camera->addAction(tr("&Ball model samples and fit..."), window, [showPanel, ballModel] { showPanel(ballModel); })
        ->setObjectName("ballModelPanel");
    camera->addSeparator();
    setUpCamera_ = camera->addAction(tr("&Set up this camera (guided: rim, body, mask, ball, distances, colours)..."), t.cameraSetup,
                                     &CameraSetup::setUp);
    setUpCamera_->setObjectName("setUpCamera");
    setUpCamera_->setStatusTip(tr("A step-by-step strip above the panes: centre and rim, robot body, mask, ball model, distance map, colours, save; each step skippable and undoable"));
    setUpCamera_->setEnabled(false);  // until a source is open
}

void WindowMenus::addSession(QMainWindow* window, const WindowMenuTargets& t)
{
    QMenu* session = window->menuBar()->addMenu(tr("&Session"));
    applyToSession_ = session->addAction(tr("&Apply to whole session"), window, t.applyToSession, QKeySequence(Qt::CTRL + Qt::Key_R));
    applyToSession_->setObjectName("applyToSession");
    applyToSession_->setIcon(QIcon(":/icons/apply-session.png"));
    applyToSession_->setStatusTip(tr("Run the current and the saved config over every frame and mark what changed"));
    applyToSession_->setEnabled(false);  // until a source is open
}

}  // namespace omnitune
