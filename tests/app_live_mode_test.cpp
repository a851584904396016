// The window's live mode with the simulated camera (issue 12), driven like a user: the camera
// opened through the real Camera > Live source action, the acquired pane updating at camera
// rate with the status bar saying "live", the Camera dock holding the camera; Space pauses
// into the replay buffer, Left / Right step through exactly the buffer's frames, Space goes
// live again; an unplugged camera stops live mode and its recording (frames kept) with a
// notice naming it and a Reconnect button that brings it back; a camera that cannot be opened leaves the source on screen.
// The Camera tab is there only while a camera is open; so is the navigator's live mode.
#include "calib/camera/SimulatedCamera.h"
#include "calib/session/SessionReader.h"
#include "widgets/CameraPanel.h"
#include "widgets/FrameNavigator.h"
#include "widgets/LiveController.h"
#include "widgets/NoticeBar.h"

#include "LiveTestSupport.h"

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QRegularExpression>
#include <QToolButton>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

bool sameImage(const cv::Mat& a, const cv::Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

// Waits until the pipeline is idle and the panes show replay frame `seq`.
bool shows(MainWindow& w, int seq) { return waitForFrame(w, seq); }

}  // namespace

class LiveModeTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { isolateRecoveryFiles(); }

    void menuOpensTheCameraAndThePanesGoLive()
    {
        MainWindow w;
        QVERIFY(showActive(w));
        QVERIFY(openSimulatedCamera(w));
        QVERIFY(w.navigator()->isPlaying());
        QVERIFY(w.windowTitle().contains("simulated camera"));
        auto* dock = w.findChild<QDockWidget*>("camera");
        QVERIFY(dock && dock->isVisible());
        QVERIFY(w.cameraPanel()->spinBox(CameraFeatureId::Exposure));  // the panel has the camera
        // The acquired pane's image changes from frame to frame (sensor noise, the robot moves).
        const auto first = w.lastRun();
        QTRY_VERIFY_WITH_TIMEOUT(w.lastRun()->frameIndex >= first->frameIndex + 3, 20000);
        QVERIFY(!sameImage(w.lastRun()->frame, first->frame));
        QVERIFY(w.live()->replay()->size() >= 4);
        QTRY_VERIFY(w.live()->statusLabel()->text().startsWith(QString::fromUtf8("live \u00b7 ")));
        QVERIFY(w.live()->statusLabel()->text().contains("dropped"));

        // docs/images/live-camera.png: OMNITUNE_SCREENSHOT=FILE (run under xvfb-run) grabs the
        // window live and recording.
        const QString shot = qEnvironmentVariable("OMNITUNE_SCREENSHOT");
        if (shot.isEmpty()) return;
        QTemporaryDir dir;
        QCOMPARE(w.live()->startRecording(dir.path() + "/run"), QString());
        QTRY_VERIFY_WITH_TIMEOUT(w.live()->recorder()->status().written >= 60, 60000);
        QVERIFY(w.grab().save(shot));
    }

    void theCameraTabAndLiveModeGoWithTheCamera()
    {
        QTemporaryDir dir;
        const QString session = freshDemo(dir);
        QVERIFY(!session.isEmpty());
        MainWindow w;
        QVERIFY(showActive(w));
        auto* dock = w.findChild<QDockWidget*>("camera");
        auto* thresholds = w.findChild<QDockWidget*>("thresholds");
        QVERIFY(dock && thresholds);
        QVERIFY(!dock->isVisible());  // no camera yet: no tab saying "No camera"
        QVERIFY(openSimulatedCamera(w));
        QVERIFY(dock->isVisible());
        QTRY_VERIFY(!dock->visibleRegion().isEmpty());  // the tab in front
        // Live: the navigator plays as live and ticks no frames of its own (the grab timer does).
        QVERIFY(w.navigator()->isLive());
        QVERIFY(w.navigator()->isPlaying());
        QVERIFY(!w.navigator()->isTicking());

        // A recorded source replaces the camera: the tab goes, the thresholds come to the front,
        // and the navigator plays the recording on its own timer again.
        QVERIFY(w.openSource(session));
        QVERIFY(waitForFrame(w, 0));
        QVERIFY(!w.live()->isOpen());
        QVERIFY(!dock->isVisible());
        QTRY_VERIFY(!thresholds->visibleRegion().isEmpty());
        QVERIFY(!w.navigator()->isLive());
        QTest::keyClick(&w, Qt::Key_Space);
        QVERIFY(w.navigator()->isPlaying());
        QVERIFY(w.navigator()->isTicking());
        QTest::keyClick(&w, Qt::Key_Space);

        // The camera again: the tab is back.
        QVERIFY(openSimulatedCamera(w));
        QVERIFY(dock->isVisible());
    }

    void pauseStepsThroughTheReplayBuffer()
    {
        MainWindow w;
        QVERIFY(showActive(w));
        QVERIFY(openSimulatedCamera(w));
        const ReplayBuffer* ring = w.live()->replay();
        QTRY_VERIFY_WITH_TIMEOUT(ring->size() >= 6, 20000);
        QTest::keyClick(&w, Qt::Key_Space);  // pause
        QVERIFY(!w.navigator()->isPlaying());
        const int size = ring->size();
        QVERIFY(shows(w, ring->newestSeq()));  // a frame still waiting for the pipeline is shown last
        QCOMPARE(ring->size(), size);  // frozen: nothing grabbed while paused
        QCOMPARE(w.navigator()->frameCount(), size);
        QCOMPARE(w.navigator()->current(), size - 1);
        QVERIFY(w.live()->statusLabel()->text().startsWith("paused"));

        const auto expect = [&](int position) {
            const int seq = ring->seqAt(position);
            QVERIFY(shows(w, seq));
            Frame f;
            QVERIFY(ring->find(seq, f));
            QVERIFY(sameImage(w.lastRun()->frame, f.image));  // exactly the buffer's frame
            QCOMPARE(w.navigator()->current(), position);
        };
        QTest::keyClick(&w, Qt::Key_Left);
        QTest::keyClick(&w, Qt::Key_Left);
        expect(size - 3);
        QTest::keyClick(&w, Qt::Key_Right);
        expect(size - 2);
        QCOMPARE(ring->size(), size);

        const int newest = ring->newestSeq();
        QTest::keyClick(&w, Qt::Key_Space);  // live again
        QVERIFY(w.navigator()->isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(w.lastRun()->frameIndex > newest, 20000);
        QTRY_VERIFY(w.live()->statusLabel()->text().startsWith("live"));
    }

    void unplugStopsLiveModeAndReconnectResumes()
    {
        MainWindow w;
        QVERIFY(showActive(w));
        QVERIFY(openSimulatedCamera(w));
        QTemporaryDir dir;
        const QString folder = dir.path() + "/unplugged";
        QCOMPARE(w.live()->startRecording(folder), QString());
        QTRY_VERIFY_WITH_TIMEOUT(w.live()->recorder()->status().written >= 3, 20000);
        auto* camera = dynamic_cast<SimulatedCamera*>(w.live()->camera());
        QVERIFY(camera);
        camera->simulateUnplug();
        QTRY_VERIFY_WITH_TIMEOUT(w.notices()->text().contains("The camera stopped"), 20000);
        const QString notice = w.notices()->text();
        QVERIFY2(notice.contains("simulated camera") && notice.contains("unplugged"), qPrintable(notice));
        // The recording ends with its frames kept and the session closed.
        QVERIFY(!w.live()->isRecording());
        const QRegularExpressionMatch m = QRegularExpression("(\\d+) frames written").match(notice);
        QVERIFY2(m.hasMatch(), qPrintable(notice));
        SessionOpen recorded = SessionReader::open(folder.toStdString());
        QVERIFY(recorded.ok());
        QCOMPARE(recorded.reader->frameCount(), m.captured(1).toInt());
        QVERIFY(recorded.reader->frameCount() >= 3);
        QVERIFY(recorded.reader->info().complete.value_or(false));
        QVERIFY(!w.navigator()->isPlaying());
        QCOMPARE(w.live()->statusLabel()->text(), QString("camera stopped"));
        QVERIFY(!w.cameraPanel()->spinBox(CameraFeatureId::Exposure));  // let go of the dead camera
        // Play does not grab from a dead camera (no second notice, no crash).
        QTest::keyClick(&w, Qt::Key_Space);
        QTRY_VERIFY(!w.navigator()->isPlaying());

        QToolButton* reconnect = nullptr;
        for (auto* b : w.notices()->findChildren<QToolButton*>())
            if (b->isVisible() && b->defaultAction() == w.live()->reconnectAction()) reconnect = b;
        QVERIFY2(reconnect, "a Reconnect button in the notice");
        const int newest = w.live()->replay()->newestSeq();
        QTest::mouseClick(reconnect, Qt::LeftButton);
        QVERIFY(w.navigator()->isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(w.lastRun()->frameIndex > newest + 2, 20000);
        QVERIFY(w.cameraPanel()->spinBox(CameraFeatureId::Exposure));
    }

    void simulatedCameraOffersItsFittedConfigAsOneUndoStep()
    {
        MainWindow w;
        QVERIFY(showActive(w));
        const Config before = w.document()->config();
        QVERIFY(openSimulatedCamera(w));
        // The window's config is the built-in default: a notice with the fitted config's button.
        QAction* use = w.live()->useFittedConfigAction();
        QVERIFY(use->isEnabled());
        QVERIFY2(w.notices()->text().contains("fitted to the simulated camera"), qPrintable(w.notices()->text()));
        QToolButton* button = nullptr;
        for (auto* b : w.notices()->findChildren<QToolButton*>())
            if (b->isVisible() && b->defaultAction() == use) button = b;
        QVERIFY2(button, "a button for the fitted config in the notice");
        const auto* camera = dynamic_cast<SimulatedCamera*>(w.live()->camera());
        QVERIFY(camera);
        const std::optional<Config> fitted = camera->fittedConfig(before);
        QVERIFY(fitted);
        QVERIFY(fitted->geometry.centerX != before.geometry.centerX || fitted->geometry.outerRadius != before.geometry.outerRadius);
        const int undoSteps = w.document()->undoStack()->count();
        QTest::mouseClick(button, Qt::LeftButton);
        QCOMPARE(w.document()->undoStack()->count(), undoSteps + 1);
        QCOMPARE(w.document()->config().geometry.centerX, fitted->geometry.centerX);
        QCOMPARE(w.document()->config().geometry.outerRadius, fitted->geometry.outerRadius);
        QVERIFY(!use->isEnabled());
        // The live runs use it, and the panes no longer fill with candidates from beyond the mirror.
        QTRY_VERIFY_WITH_TIMEOUT(w.lastRun()->config.geometry.outerRadius == fitted->geometry.outerRadius, 20000);
        w.document()->undoStack()->undo();  // one step takes it all back
        QCOMPARE(w.document()->config().geometry.centerX, before.geometry.centerX);
        QCOMPARE(w.document()->config().geometry.outerRadius, before.geometry.outerRadius);

        // A config that fits the simulated camera (its own fitted one) is left alone.
        w.document()->reset(*fitted);  // (clean: opening asks nothing)
        QVERIFY(w.openCamera("simulated", SimulatedStart::Dark));
        QVERIFY(!w.live()->useFittedConfigAction()->isEnabled());
        QVERIFY(!w.notices()->text().contains("fitted to the simulated camera"));
    }

    void liveSliderRecordingWhilePausedAndTheSameCameraAgain()
    {
        MainWindow w;
        QVERIFY(showActive(w));
        QVERIFY(openSimulatedCamera(w));
        const ReplayBuffer* ring = w.live()->replay();
        QTRY_VERIFY_WITH_TIMEOUT(ring->size() >= 4, 20000);
        // Live, the slider holds exactly the buffer's frames and sits on the newest.
        QCOMPARE(w.navigator()->frameCount(), ring->size());
        QCOMPARE(w.navigator()->current(), ring->size() - 1);
        // The playback speed box is for recordings: the camera keeps its rate.
        const int period = w.live()->grabIntervalMs();
        QCOMPARE(period, int(1000.0 / w.document()->config().camera.frameRate));
        auto* speed = w.navigator()->findChild<QComboBox*>();
        QVERIFY(speed);
        speed->setCurrentIndex(speed->count() - 1);  // 4x
        QCOMPARE(w.live()->grabIntervalMs(), period);
        QVERIFY(w.navigator()->isPlaying());

        // Paused while recording: the view holds still, the recording goes on.
        QTemporaryDir dir;
        QCOMPARE(w.live()->startRecording(dir.path() + "/paused"), QString());
        QTest::keyClick(&w, Qt::Key_Space);
        QVERIFY(!w.navigator()->isPlaying());
        QVERIFY(w.live()->isRecording());
        const int size = ring->size();
        const int newest = ring->newestSeq();
        const int written = w.live()->recorder()->status().written;
        QTRY_VERIFY_WITH_TIMEOUT(w.live()->recorder()->status().written >= written + 10, 20000);
        QCOMPARE(ring->size(), size);
        QCOMPARE(ring->newestSeq(), newest);
        QVERIFY(w.live()->statusLabel()->text().contains("recording goes on"));
        w.live()->stopRecording();

        // Choosing the live camera again keeps its handle (a real device would refuse a second one).
        Camera* camera = w.live()->camera();
        auto* again = w.findChild<QAction*>("cameraSource:simulated");
        QVERIFY(again);
        again->trigger();
        QCOMPARE(w.live()->camera(), camera);
        QVERIFY2(w.notices()->text().contains("is the live camera already"), qPrintable(w.notices()->text()));
        QVERIFY(w.navigator()->isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(ring->newestSeq() > newest + 2, 20000);
        // Another start of the simulated camera is another camera: opened afresh.
        w.findChild<QAction*>("cameraSource:simulated:dark")->trigger();
        QVERIFY(w.live()->isOpen());
        QVERIFY(w.live()->camera() != camera || w.live()->camera()->description().find("dark") != std::string::npos);
    }

    void aCameraThatCannotOpenLeavesTheSourceOnScreen()
    {
        QTemporaryDir dir;
        QVERIFY(copyDemo(dir.path()));
        MainWindow w;
        QVERIFY(showActive(w));
        QVERIFY(w.openSource(dir.path()));
        QVERIFY(waitForFrame(w, 0));
        const QString title = w.windowTitle();
        QVERIFY(!w.openCamera("v4l2:/dev/omnitune-no-such-camera"));
        QVERIFY2(w.notices()->text().contains("Cannot open the camera") && w.notices()->text().contains("omnitune-no-such-camera"),
                 qPrintable(w.notices()->text()));
        QVERIFY(!w.live()->isOpen());
        QCOMPARE(w.windowTitle(), title);
        w.navigator()->goTo(1);
        QVERIFY(waitForFrame(w, 1));  // the session still plays
    }
};

QTEST_MAIN(LiveModeTest)
#include "app_live_mode_test.moc"
