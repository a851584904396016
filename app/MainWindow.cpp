#include "app/MainWindow.h"

#include "widgets/BallModelPanel.h"
#include "widgets/CameraPanel.h"
#include "widgets/CameraSetup.h"
#include "widgets/CameraSetupBar.h"
#include "widgets/CandidateTableModel.h"
#include "widgets/CandidateTableView.h"
#include "widgets/ColourEditor.h"
#include "widgets/ColourSampler.h"
#include "widgets/ConfigFiles.h"
#include "widgets/DistancePointsPanel.h"
#include "widgets/FrameNavigator.h"
#include "widgets/GeometryEditor.h"
#include "widgets/LiveController.h"
#include "calib/source/FrameSourceFactory.h"
#include "widgets/MarkedSlider.h"
#include "widgets/MaskEditor.h"
#include "widgets/PaneEditors.h"
#include "widgets/NoticeBar.h"
#include "widgets/PipelineView.h"
#include "widgets/PixelInspector.h"
#include "widgets/RecordBar.h"
#include "widgets/RayStrip.h"
#include "widgets/RecentFiles.h"
#include "widgets/ScreenFit.h"
#include "widgets/RecoveryFile.h"
#include "widgets/RecoveryOffer.h"
#include "widgets/RunSummary.h"
#include "widgets/SaveAsSession.h"
#include "calib/session/Session.h"
#include "calib/source/SessionSource.h"
#include "widgets/SetupSequence.h"
#include "widgets/SetupSteps.h"
#include "widgets/StatusMessages.h"
#include "widgets/ThresholdPanel.h"
#include "widgets/TruthMarker.h"
#include "widgets/WholeSessionRun.h"
#include "widgets/WindowDocks.h"
#include "widgets/WindowMenus.h"

#include <QAction>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QIcon>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>

// The icons (resources/omnitune.qrc) are in a static library: the window pulls them in.
static void initResources() { Q_INIT_RESOURCE(omnitune); }

namespace omnitune {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), view_(new PipelineView(this)), nav_(new FrameNavigator(this)),
      panel_(new ThresholdPanel(&doc_, this)), candidates_(new CandidateTableModel(this)),
      marker_(new TruthMarker(&truth_, view_, doc_.undoStack(), this)), summary_(new RunSummary(this)), pixelLabel_(new QLabel(this))
{
    initResources();
    setWindowIcon(QIcon(":/icons/omnitune.png"));
    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    notices_ = new NoticeBar(this);
    configFiles_ = new ConfigFiles(&doc_, notices_, this);
    showMessagesOnStatusBar(this, configFiles_, &ConfigFiles::message, kShortMessageMs);
    layout->addWidget(notices_);
    auto* setupBar = new CameraSetupBar(this);
    cameraSetup_ = new CameraSetup(&doc_, configFiles_, notices_, setupBar, this);
    layout->addWidget(setupBar);
    layout->addWidget(view_, 1);
    rayStrip_ = new RayStrip(this);  // the classes along a radial sensor ray, while they are edited
    layout->addWidget(rayStrip_);
    layout->addWidget(summary_);
    cameraPanel_ = new CameraPanel(this);
    live_ = new LiveController(&doc_, nav_, &runner_, cameraPanel_, this);
    layout->addWidget(live_->recordBar());
    layout->addWidget(nav_);
    setCentralWidget(central);

    colours_ = new ColourEditor(&doc_, view_, this);
    docks_ = new WindowDocks(this, panel_, colours_, cameraPanel_, live_);
    connect(this, &MainWindow::runShown, colours_, [this] { colours_->setRun(lastRun_); });
    showMessagesOnStatusBar(this, colours_, &ColourEditor::message);

    auto* table = new CandidateTableView(candidates_, this);
    view_->setSideWidget(table);
    connect(table, &CandidateTableView::candidateClicked, view_->transform(), &ViewTransform::centerOn);

    statusBar()->addWidget(pixelLabel_, 1);
    statusBar()->addPermanentWidget(live_->statusLabel());
    statusBar()->addPermanentWidget(summary_->timingLabel());

    connect(nav_, &FrameNavigator::frameRequested, this, [this](int index) {
        if (!live_->handleNavigation(index)) showFrame(index);  // live: a tick or a step in the replay buffer
    });
    connect(live_, &LiveController::frameWanted, this, &MainWindow::showFrame);
    connect(live_, &LiveController::sourceChosen, this, &MainWindow::openCamera);
    connect(live_, &LiveController::notice, this, [this](const QString& title, const QStringList& lines, QAction* button) {
        notices_->add(title, lines);
        if (button) notices_->addButton(button);
    });
    connect(&runner_, &PipelineRunner::finished, this, &MainWindow::onRunFinished);
    connect(&doc_, &ConfigDocument::changed, this, [this] {
        ++generation_;  // "repeat frame": every change re-runs the frame on screen
        requestRun();
        nav_->setMarksOutdated({FrameMarkKind::Detected});  // seen with the old config; renewed as frames show
    });
    connect(&doc_, &ConfigDocument::dirtyChanged, this, &MainWindow::updateTitle);
    connect(&doc_, &ConfigDocument::pathChanged, this, &MainWindow::updateTitle);
    connect(view_, &PipelineView::hovered, this, [this](QPointF p) {
        pixelLabel_->setText(lastRun_ ? describePixel(*lastRun_, lastRun_->config, p) : QString());
    });
    connect(view_, &PipelineView::left, pixelLabel_, &QLabel::clear);
    connect(marker_, &TruthMarker::advanceRequested, this, [this] {
        // Never round to frame 0 (its mark would be next to be overwritten), loop or not.
        if (nav_->current() + 1 < nav_->frameCount())
            nav_->next();
        else
            statusBar()->showMessage(tr("Last frame marked; U finds the frames still unmarked"), kMessageMs);
    });
    connect(marker_, &TruthMarker::frameRequested, nav_, &FrameNavigator::goTo);
    connect(marker_, &TruthMarker::markingRefused, this, &MainWindow::offerSessionForTruth, Qt::QueuedConnection);
    showMessagesOnStatusBar(this, marker_, &TruthMarker::message);
    connect(marker_, &TruthMarker::described, this, [this](const QString& text) { summary_->setTruth(text, marker_->isMarking()); });
    connect(&truth_, &TruthDocument::changed, this, [this](int frame) {
        if (frame >= 0) {
            nav_->setMark(frame, FrameMarkKind::Truth, truth_.row(frame) != nullptr);
            return;
        }
        QVector<FrameMark> marks;
        for (const auto& entry : truth_.rows()) marks.push_back({entry.first, FrameMarkKind::Truth});
        nav_->setMarks(marks, {FrameMarkKind::Truth});
    });
    showMessagesOnStatusBar(this, panel_, &ThresholdPanel::editRefused);
    // Escape leaves an editor (a threshold, the frame box): the panes take the keyboard back,
    // so arrows, Space and T act on frames again.
    auto* escape = new QAction(this);
    escape->setShortcut(Qt::Key_Escape);
    connect(escape, &QAction::triggered, view_, [this] {
        paneEditors_->escape();  // an open polygon first, then the mask or sensor editing
        view_->setFocus(Qt::ShortcutFocusReason);
    });
    addAction(escape);
    recovery_ = new RecoveryFile(&doc_, this);
    connect(recovery_, &RecoveryFile::writeFailed, this, [this](const QString& why) { notices_->add(tr("Crash recovery:"), {why}); });

    setAcceptDrops(true);  // a session folder, video, image or config.yml dropped on the window opens
    buildEditors();
    menus_ = new WindowMenus(this, {&doc_, view_, nav_, live_, geometryEditor_, colours_, paneEditors_, cameraSetup_, marker_,
                                    [this] { chooseSource(); }, [this] { chooseSourceFile(); }, [this] { chooseConfig(); },
                                    [this](const QString& path) { openPath(path); }, [this] { saveConfig(); },
                                    [this] { saveConfigAs(); }, [this] { saveAsSession(); }, [this] { applyToSession(); },
                                    [this](QWidget* w) { showPanel(w); }, ballModel_});
    recent_ = menus_->recentFiles();
    updateTitle();
    fitToScreen(this, QSize(1366, 768));  // a 1366x768 laptop: every dock and the status bar on screen
}

MainWindow::~MainWindow()
{
    // The documents outlive the widgets and labels declared after them; a dirty undo stack
    // still signals "clean" while it is destroyed. Nothing may reach the half-destroyed window.
    live_->close();  // ends a recording and lets the panel go of the camera while both exist
    delete recovery_;  // listens to the undo stack, which signals while it is destroyed
    recovery_ = nullptr;
    doc_.disconnect();
    truth_.disconnect();
    delete wholeSession_;  // stops its thread before the members it reports to go
    wholeSession_ = nullptr;
}

void MainWindow::buildEditors()
{
    // Each one's filters on the panes are installed in this order (the last one sees events first).
    geometryEditor_ = new GeometryEditor(&doc_, view_, this);
    showMessagesOnStatusBar(this, geometryEditor_, &GeometryEditor::message, kShortMessageMs);
    // The pane editors, the geometry editor, truth marking and colour sampling: one of them holds
    // the left button at a time (PaneEditors arbitrates; sampling lets go of it and takes it).
    paneEditors_ = new PaneEditors(&doc_, view_, geometryEditor_, marker_, rayStrip_, this);
    addToolBar(Qt::TopToolBarArea, paneEditors_->mask()->toolBar());
    showMessagesOnStatusBar(this, paneEditors_, &PaneEditors::message);
    connect(paneEditors_, &PaneEditors::leftButtonTaken, colours_->sampler(), [this] { colours_->sampler()->setSampling(false); });
    connect(colours_->sampler(), &ColourSampler::samplingChanged, this, [this](bool on) {
        if (!on) return;
        paneEditors_->releaseLeftButton();
        docks_->colours()->raise();  // sampling goes to the class selected there
    });
    paneEditors_->distances()->hide();
    ballModel_ = new BallModelPanel(&doc_, &truth_, this);
    ballModel_->hide();
    showMessagesOnStatusBar(this, ballModel_, &BallModelPanel::message);
    wholeSession_ = new WholeSessionRun(&doc_, &truth_, nav_, ballModel_, docks_, this);
    connect(wholeSession_, &WholeSessionRun::rerunRequested, this, &MainWindow::applyToSession);
    connect(wholeSession_, &WholeSessionRun::finished, this, [this](const QString& text) { statusBar()->showMessage(text, kMessageMs); });
    connect(wholeSession_, &WholeSessionRun::failed, this,
            [this](const QString& why) { notices_->add(tr("Apply to whole session failed:"), {why}); });
    // The guided set-up: a strip above the panes (under the yellow bar).
    setupSequence_ = new SetupSequence(this);
    qobject_cast<QBoxLayout*>(centralWidget()->layout())->insertWidget(2, setupSequence_);
    // The strip reports each step; the notices from before it would only push the panes down.
    connect(cameraSetup_, &CameraSetup::sequenceRequested, notices_, &NoticeBar::clear);
    connect(cameraSetup_, &CameraSetup::sequenceRequested, setupSequence_, &SetupSequence::start);
    connectSetupSteps(*setupSequence_, {&doc_, cameraSetup_, geometryEditor_, paneEditors_->mask(), ballModel_,
                                        paneEditors_->distances(), colours_, [this](QWidget* w) { showPanel(w); },
                                        [this] { return saveConfig(); }});
    // An image folder or video becomes a session folder, so it can be marked and evaluated.
    saveAsSession_ = new SaveAsSession(this);
    showMessagesOnStatusBar(this, saveAsSession_, &SaveAsSession::message);
}

bool MainWindow::openSource(const QString& path)
{
    SourceOpen<FrameSource> opened = openFrameSource(path.toStdString());
    if (!opened.ok()) {
        QMessageBox::warning(this, tr("Cannot open"), QString::fromStdString(opened.error));
        return false;
    }
    if (!maybeKeepTruth()) return false;
    // Unsaved edits never travel to another source unasked (Cancel keeps the current one open).
    if (!configFiles_->maybeSave(tr("The config has unsaved changes. Save them before opening %1?").arg(QFileInfo(path).fileName()), true))
        return false;
    sourceName_ = QFileInfo(path).fileName();
    clearForNewSource();
    QStringList sourceWarnings;
    for (const auto& s : opened.warnings) sourceWarnings << QString::fromStdString(s);
    notices_->add(tr("Opened %1 with warnings:").arg(path), sourceWarnings);
    const auto* session = dynamic_cast<const SessionSource*>(opened.source.get());
    const QString sessionFolder = session ? QString::fromStdString(session->reader().folder()) : QString();
    // A session brings its own config; any other source keeps the one on screen (ConfigFiles).
    if (!session || !session->reader().hasConfig()
        || !configFiles_->openSessionConfig(QString::fromStdString(session->reader().configPath())))
        configFiles_->keepFor(sourceName_, path, sessionFolder);
    // Edits an earlier run left unsaved for the config now on screen (or for the defaults),
    // offered only while nothing of this run is unsaved, so they never mix with live edits.
    if (!doc_.isDirty()) offerRecoveredEdits();
    source_ = std::move(opened.source);
    sourcePath_ = path;  // Apply to whole session re-opens it in a thread of its own
    menus_->applyToSession()->setEnabled(true);
    menus_->saveAsSession()->setEnabled(true);
    menus_->setUpCamera()->setEnabled(true);
    cameraSetup_->setSource(path);
    ballModel_->setDetections({});  // detections of the previous source
    wholeSession_->reset();  // its results belong to the previous source
    nav_->setFrameCount(source_->frameCount());
    nav_->setFrameRate(doc_.config().camera.frameRate);
    marker_->reset(source_->frameCount());
    openTruth(sessionFolder, session ? cv::Size(session->reader().info().width, session->reader().info().height) : cv::Size());
    recent_->add(path);
    updateTitle();
    showFrame(0);
    return true;
}

bool MainWindow::openCamera(const QString& source, SimulatedStart start)
{
    CameraOpen opened = LiveController::openCamera(source, start, doc_.config());
    if (!opened.ok()) {
        notices_->add(tr("Cannot open the camera (the source on screen stays):"), {QString::fromStdString(opened.error->message)});
        return false;
    }
    const QString name = QString::fromStdString(opened.camera->description());
    if (!maybeKeepTruth()) return false;
    if (!configFiles_->maybeSave(tr("The config has unsaved changes. Save them before opening %1?").arg(name), true)) return false;
    sourceName_ = name;
    clearForNewSource();
    configFiles_->keepFor(sourceName_, QDir::current().filePath(QStringLiteral("camera")), QString());
    // A simulated camera started badly set keeps its bad start (to try the calibration on).
    source_ = live_->start(std::move(opened.camera), start == SimulatedStart::Good);
    sourcePath_.clear();  // nothing to re-open: no whole-session sweep, no camera set-up from files
    menus_->applyToSession()->setEnabled(false);
    menus_->setUpCamera()->setEnabled(false);
    wholeSession_->reset();
    marker_->reset(0);
    openTruth(QString(), cv::Size());
    updateTitle();
    return true;
}

void MainWindow::clearForNewSource()
{
    live_->close();  // a camera open before goes (its recording ends, frames kept)
    // Nothing of the previous source may stay on screen under the new title: panes, overlays,
    // table and labels are emptied now, and runs of the old source still in flight are dropped.
    ++sourceTag_;
    geometryEditor_->setEditing(false);  // the marker gives up the left button too (TruthMarker::reset)
    paneEditors_->stopEditing();
    source_.reset();  // a config loaded (or restored) before the new source is set runs nothing old
    lastRun_.reset();
    marker_->setRun(nullptr);
    colours_->setRun(nullptr);  // strokes sample nothing of the previous source
    view_->clear(tr("Opening %1: reading its first frame...").arg(sourceName_));
    candidates_->clear();
    summary_->opening(sourceName_);
    pixelLabel_->clear();
    notices_->clear();  // they were about the previous source
}

void MainWindow::openTruth(const QString& sessionFolder, cv::Size frameSize)
{
    if (sessionFolder.isEmpty()) {  // truth.csv belongs to a session folder (docs/sessions.md)
        truth_.close(tr("this source is not a session folder; ground truth is kept in a session's truth.csv"));
        return;
    }
    QStringList warnings;
    if (const auto why = truth_.open(sessionFolder, &warnings, TruthLimits{frameSize}))
        notices_->add(tr("Ground truth cannot be marked:"), {*why});
    else
        notices_->add(tr("Ground truth (truth.csv):"), warnings);
}

bool MainWindow::openConfig(const QString& path)
{
    if (!configFiles_->open(path)) return false;
    offerRecoveredEdits();
    return true;
}

void MainWindow::offerRecoveredEdits()
{
    notices_->add(tr("Crash recovery:"), offerRecovery(this, *recovery_, doc_));
}

bool MainWindow::openPath(const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == "yml" || suffix == "yaml") {
        if (QFileInfo(path).fileName() == QString::fromUtf8(kSessionInfoFile.data(), int(kSessionInfoFile.size())))
            return openSource(path);  // session.yml opens its session
        if (!configFiles_->maybeSave(tr("The config has unsaved changes. Save them before opening %1?").arg(QFileInfo(path).fileName()), false)
            || !openConfig(path))
            return false;
        recent_->add(path);  // only configs opened by hand: a session's own comes with it
        return true;
    }
    return openSource(path);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.front().isLocalFile()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() != 1 || !urls.front().isLocalFile()) return;
    event->acceptProposedAction();
    // Opening may ask about unsaved changes: not from inside the drop, which holds the
    // dragging application waiting.
    const QString path = urls.front().toLocalFile();
    QTimer::singleShot(0, this, [this, path] { openPath(path); });
}

void MainWindow::showFrame(int index)
{
    if (!source_) return;
    frameIndex_ = index;
    nav_->setCurrent(index);
    marker_->setFrame(index);  // marks wait for this frame's run; the panes still show the last one
    requestRun();
}

void MainWindow::requestRun()
{
    if (source_) runner_.request(source_, sourceTag_, frameIndex_, doc_.config(), generation_);
}

bool MainWindow::isProcessing() const { return runner_.isBusy(); }

void MainWindow::onRunFinished(std::shared_ptr<const PipelineRun> run)
{
    if (run->sourceTag != sourceTag_) return;  // a frame of the source open before this one
    lastRun_ = run;
    marker_->setRun(run);  // the truth drawn is this frame's, whatever the slider asks for next
    paneEditors_->setRun(run);
    if (!run->error.isEmpty() || !run->result.ok()) {
        // Shown all the same (when it could be read), with the reason on it: never another frame.
        const QString why = run->error.isEmpty() ? QString::fromStdString(run->result.error) : run->error;
        const QString text = run->frameUnreadable ? tr("Frame %1 skipped: %2").arg(run->frameIndex).arg(why)
                                                  : tr("Frame %1 not processed: %2").arg(run->frameIndex).arg(why);
        view_->showUnprocessed(*run, text);
        const cv::Size configSize(run->config.geometry.imageWidth, run->config.geometry.imageHeight);
        if (!run->frameUnreadable && !run->frame.empty() && run->frame.size() != configSize)
            cameraSetup_->frameSizeMismatch(run->frame.size());
        candidates_->clear();
        summary_->showUnprocessed(*run, text);
        emit runShown(run->frameIndex);
        return;
    }
    auto overlay = std::make_shared<OverlayData>();
    overlay->config = run->config;
    overlay->maskOutline = run->maskOutline;
    overlay->maskTint = run->maskTint;
    overlay->candidates = run->result.candidates;
    overlay->detection = run->result.detection;
    view_->showRun(*run, overlay);
    candidates_->setResult(run->result, run->config);

    const BallDetection& d = run->result.detection;
    if (!live_->isOpen())  // live frames are numbered by the replay buffer, not by slider places
        nav_->setMark(run->frameIndex, FrameMarkKind::Detected, d.found);  // the slider marks every frame seen with a ball
    summary_->showResult(*run);
    emit runShown(run->frameIndex);
}

void MainWindow::showPanel(QWidget* panel)
{
    if (panel == ballModel_)
        docks_->show(panel, tr("Ball model"), QStringLiteral("ballModel"));
    else
        docks_->show(panel, tr("Distance map"), QStringLiteral("distanceMap"));
}

bool MainWindow::saveAsSession()
{
    if (!maybeKeepTruth()) return false;
    const QString folder = saveAsSession_->save(sourcePath_, doc_.config());
    if (folder.isEmpty()) return false;
    // The new session's config.yml holds the edits on screen: opening it asks nothing about them.
    if (doc_.isDirty()) doc_.discardChanges();
    return openSource(folder);
}

void MainWindow::offerSessionForTruth()
{
    if (!source_ || dynamic_cast<const SessionSource*>(source_.get())) return;  // a session's own reason stands
    if (QMessageBox::question(this, tr("Mark ground truth"),
                              tr("Ground truth is kept in a session folder's truth.csv, and %1 is not a session.\n\n"
                                 "Save it as a session (its frames and this config in a new folder), open that and mark there?")
                                  .arg(sourceName_))
            == QMessageBox::Yes
        && saveAsSession())
        marker_->setMarking(true);
}

bool MainWindow::saveConfig() { return configFiles_->save(); }

bool MainWindow::saveConfigAs() { return configFiles_->saveAs(); }

bool MainWindow::maybeKeepTruth()
{
    if (!truth_.hasUnsavedMarks()) return true;
    const auto err = truth_.save();
    if (!err) return true;
    return QMessageBox::warning(this, tr("Unsaved ground truth"),
                                tr("Ground-truth marks could not be saved: %1\n\nDiscard them?").arg(*err),
                                QMessageBox::Discard | QMessageBox::Cancel) == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (maybeKeepTruth() && configFiles_->maybeSave(tr("The config has unsaved changes. Save them first?"), false)) {
        recovery_->discard();  // saved, or dropped on purpose
        event->accept();
    } else
        event->ignore();
}

void MainWindow::chooseSource()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open a session or image folder"));
    if (!dir.isEmpty()) openSource(dir);
}

void MainWindow::chooseSourceFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a video or an image"), QString(),
                                                      tr("Videos and images (*.avi *.mp4 *.mkv *.mov *.png *.jpg *.jpeg *.bmp);;All files (*)"));
    if (!path.isEmpty()) openSource(path);
}

void MainWindow::chooseConfig()
{
    const QString path = configFiles_->choose();
    if (path.isEmpty()) return;
    offerRecoveredEdits();  // edits a crashed run left unsaved for this config
    recent_->add(path);
}

void MainWindow::updateTitle()
{
    const QString config = configFiles_->name();
    setWindowTitle(tr("OmniTune - %1 - %2[*]").arg(sourceName_.isEmpty() ? tr("no source") : sourceName_, config));
    setWindowModified(doc_.isDirty());
}

void MainWindow::applyToSession()
{
    if (!sourcePath_.isEmpty()) wholeSession_->start(sourcePath_);
}

}  // namespace omnitune
