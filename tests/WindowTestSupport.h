#pragma once
// Shared by the offscreen tests of the workbench window: a scratch copy of the demo session,
// answering modal message boxes, and waiting (event driven) for a frame's run.
#include "app/MainWindow.h"
#include "widgets/CameraSetup.h"
#include "widgets/ImageView.h"
#include "widgets/SetupSequence.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDirIterator>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>
#include <memory>

namespace omnitune::testing {

// Crash-recovery files of the windows a test makes go to a folder of this run's own, never to
// the shared test-mode data folder: a file left there by another run (the sanitizer build's
// tests have the same names) would open a modal "Recover unsaved edits" box in the next one.
inline void isolateRecoveryFiles()
{
    static QTemporaryDir dir;
    qputenv("OMNITUNE_RECOVERY_DIR", dir.path().toUtf8());
}

// Copies the demo session (the repository's copy must never change).
inline bool copyDemo(const QString& to)
{
    const QString from = QStringLiteral(OMNITUNE_SOURCE_DIR "/sessions/demo");
    QDirIterator it(from, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QString target = to + file.mid(from.size());
        QDir().mkpath(QFileInfo(target).path());
        if (!QFile::copy(file, target)) return false;
    }
    return true;
}

// What every window test's initTestCase does first: recent files and the other settings in
// the test location (not the user's) and emptied, crash-recovery files in this run's own folder.
inline void startWindowTests()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    isolateRecoveryFiles();
}

// A new copy of the demo session in a folder of its own under `dir`; empty when copying failed.
inline QString freshDemo(const QTemporaryDir& dir)
{
    static int copies = 0;
    const QString session = dir.filePath(QStringLiteral("demo-%1").arg(++copies));
    return copyDemo(session) ? session : QString();
}

// Answers the next modal message box with `button` and keeps its text. Event driven: checks
// again on every turn of the event loop until the box is there.
inline void answerNextMessageBox(QMessageBox::StandardButton button, QString* text)
{
    QTimer::singleShot(0, [button, text] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            if (text) *text = box->text();
            box->button(button)->click();
            return;
        }
        answerNextMessageBox(button, text);
    });
}

// Shows the window at a laptop's size and makes it active, so that its shortcuts reach it
// (under a real X server too, where a window that is not active gets no key events).
inline bool showActive(MainWindow& window)
{
    window.resize(1300, 750);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return false;
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

enum class Shown { AsIs, Active };

// A new window on `session` with frame 0 on the panes. `Shown::Active` shows it at a laptop's
// size and active (tests that send keys); `beforeOpen` runs between showing and opening.
inline bool openWindow(std::unique_ptr<MainWindow>& window, const QString& session, Shown shown,
                       const std::function<void(MainWindow&)>& beforeOpen = nullptr);

// Waits until the window shows a run of `frame` and nothing is pending (about 10 s at most).
inline bool waitForFrame(MainWindow& window, int frame)
{
    QSignalSpy spy(&window, &MainWindow::runShown);
    for (int i = 0; i < 50; ++i) {
        if (!window.isProcessing() && window.lastRun() && window.lastRun()->frameIndex == frame) return true;
        spy.wait(200);
    }
    return false;
}

inline bool openWindow(std::unique_ptr<MainWindow>& window, const QString& session, Shown shown,
                       const std::function<void(MainWindow&)>& beforeOpen)
{
    window = std::make_unique<MainWindow>();
    if (shown == Shown::Active) {
        if (!showActive(*window)) return false;
    } else {
        window->show();
    }
    if (beforeOpen) beforeOpen(*window);
    return window->openSource(session) && waitForFrame(*window, 0);
}

// The frames the set-up's rim, body and mask fits read in the tests: enough for them, and
// quicker than the 16 a user gets.
constexpr int kSetupTestFrames = 8;

// The set-up tests' window: shown active at a laptop's size, the set-up's fits reading
// kSetupTestFrames, `config` opened first when given, then `source` with frame 0 on the panes.
inline bool openSetupWindow(MainWindow& window, const QString& source, const QString& config = QString())
{
    if (!showActive(window)) return false;
    window.cameraSetup()->frameCount = kSetupTestFrames;
    if (!config.isEmpty() && !window.openConfig(config)) return false;
    return window.openSource(source) && waitForFrame(window, 0);
}

// Clicks the set-up strip's Apply on its current step, which must be `step`, then Next. Empty
// when the step was applied, else what went wrong (the strip's own text when it refused).
// `applied`, when given, gets the strip's text after Apply (what it says it did).
inline QString applySetupStep(SetupSequence& seq, SetupSequence::Step step, QString* applied = nullptr)
{
    if (seq.step() != step) return QStringLiteral("the strip is at step %1, not %2").arg(int(seq.step())).arg(int(step));
    QTest::mouseClick(seq.applyButton(), Qt::LeftButton);
    if (seq.state(step) != SetupSequence::StepState::Applied) return QStringLiteral("not applied: ") + seq.text();
    if (applied) *applied = seq.text();
    QTest::mouseClick(seq.nextButton(), Qt::LeftButton);
    return QString();
}

// Drags with the left button on a pane from image point `from` to `to`, through the middle;
// returns the image points the pane reported for press and release (whole widget px).
inline std::pair<QPointF, QPointF> dragOnPane(ImageView* pane, QPointF from, QPointF to)
{
    const QPoint a = pane->toWidget(from).toPoint(), b = pane->toWidget(to).toPoint();
    QTest::mousePress(pane, Qt::LeftButton, {}, a);
    QTest::mouseMove(pane, (a + b) / 2);
    QTest::mouseMove(pane, b);
    QTest::mouseRelease(pane, Qt::LeftButton, {}, b);
    return {pane->toImage(QPointF(a)), pane->toImage(QPointF(b))};
}

}  // namespace omnitune::testing
