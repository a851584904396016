// Issue 12's done-when, walked end to end through the real window like a new user (offscreen,
// simulated camera): Camera > Live source > "started dark"; the notice's button applies the
// simulated camera's fitted config; Auto-calibrate on the Camera tab converges while its frames
// reach the replay buffer, the acquired pane and the histogram (the MSV the histogram shows
// climbs into the target band); one feature set by hand in its spin box is read back from the
// camera and used by the sensor; Camera > Record writes N frames into a new session folder
// chosen in the folder dialog, with the hand-set value in session.yml; Stop; the session opens
// in the window and Right steps through it frame by frame, each replayed frame pixel-equal to
// the PNG on disk and to the frame the live view showed. OMNITUNE_SCREENSHOT_DIR=DIR (under
// xvfb-run) saves the user guide's live-camera-*.png along the way.
#include "calib/camera/CameraAutoCalibration.h"
#include "calib/camera/SimulatedCamera.h"
#include "calib/session/SessionReader.h"
#include "core/Geometry.h"
#include "widgets/CameraPanel.h"
#include "widgets/ConfigDocument.h"
#include "widgets/FrameNavigator.h"
#include "widgets/IntensityHistogramView.h"
#include "widgets/LiveController.h"
#include "widgets/NoticeBar.h"
#include "widgets/RecordBar.h"

#include "LiveTestSupport.h"

#include <QDockWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QToolButton>

#include <opencv2/imgcodecs.hpp>

#include <cmath>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

bool sameImage(const cv::Mat& a, const cv::Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

QToolButton* noticeButton(MainWindow& w, QAction* action)
{
    for (auto* b : w.notices()->findChildren<QToolButton*>())
        if (b->isVisible() && b->defaultAction() == action) return b;
    return nullptr;
}

void screenshot(MainWindow& w, const char* name)
{
    const QString dir = qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR");
    if (dir.isEmpty()) return;
    QCoreApplication::processEvents();  // pending layouts and paints before the grab
    QVERIFY(w.grab().save(dir + "/" + name));
}

}  // namespace

class LiveDoneWhenTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { isolateRecoveryFiles(); }

    void chooseAutoCalibrateTuneRecordReplay()
    {
        MainWindow w;
        QVERIFY(showActive(w));

        // 1. Choose the simulated camera, started dark.
        auto* dark = w.findChild<QAction*>("cameraSource:simulated:dark");
        QVERIFY(dark);
        dark->trigger();
        QVERIFY(w.live()->isOpen());
        QTRY_VERIFY_WITH_TIMEOUT(w.lastRun() && w.lastRun()->error.isEmpty(), 20000);
        CameraPanel* panel = w.cameraPanel();
        auto* dock = w.findChild<QDockWidget*>("camera");
        QVERIFY(dock && dock->isVisible());
        auto* camera = dynamic_cast<SimulatedCamera*>(w.live()->camera());
        QVERIFY(camera);
        // The window's built-in geometry is not this camera's: its fitted config, one click.
        QToolButton* fit = noticeButton(w, w.live()->useFittedConfigAction());
        QVERIFY2(fit, qPrintable(w.notices()->text()));
        screenshot(w, "live-camera-choose.png");
        QTest::mouseClick(fit, Qt::LeftButton);
        const Config& config = w.document()->config();
        QCOMPARE(config.geometry.outerRadius, camera->fittedConfig(Config{})->geometry.outerRadius);
        const CameraAutoOptions& target = config.cameraAuto;
        const cv::Mat used = Geometry(config.geometry, config.mask).usedMask();
        const auto msvOf = [&](const cv::Mat& bgr) {
            CameraMeasurement m;
            const auto why = measureCameraFrame(bgr, used, target, m);
            return why ? -1.0 : m.msv;
        };
        const double darkMsv = msvOf(w.lastRun()->frame);
        QVERIFY2(darkMsv < target.msvTarget - target.msvTolerance, qPrintable(QString::number(darkMsv)));

        // 2. Auto-calibrate; watch it converge on the panes and the histogram.
        panel->setHistogramInterval(0);  // every frame, so each iteration's frame is seen here
        const ReplayBuffer* ring = w.live()->replay();
        const int seqBefore = ring->newestSeq();
        std::vector<double> histogramMsv;
        std::vector<int> paneFrames;
        const QMetaObject::Connection watch = connect(panel, &CameraPanel::calibrationIteration, this, [&] {
            histogramMsv.push_back(panel->histogramView()->msv());
            paneFrames.push_back(w.lastRun()->frameIndex);
        });
        QSignalSpy finished(panel, &CameraPanel::calibrationFinished);
        QTest::mouseClick(panel->startButton(), Qt::LeftButton);
        QVERIFY(panel->isCalibrating());
        QVERIFY(panel->stopButton()->isEnabled());
        QVERIFY(finished.wait(60000));
        disconnect(watch);
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
        const int iterations = int(histogramMsv.size());
        QVERIFY2(iterations >= 2 && iterations <= 30, qPrintable(QString::number(iterations)));
        // Every frame the calibration took went through the live view: skip_frames + 1 per iteration.
        QVERIFY(ring->newestSeq() - seqBefore >= iterations * (target.skipFrames + 1));
        // The histogram followed it from dark into the band; the acquired pane showed its frames.
        QVERIFY(histogramMsv.front() < target.msvTarget - target.msvTolerance);
        QVERIFY(std::abs(histogramMsv.back() - target.msvTarget) <= target.msvTolerance);
        QVERIFY(paneFrames.back() > paneFrames.front());
        QVERIFY(panel->revertButton()->isEnabled());
        qInfo("converged in %d iterations: MSV %.2f -> %.2f (histogram)", iterations, histogramMsv.front(), histogramMsv.back());
        // The live frames after it are in the band.
        const int seqConverged = ring->newestSeq();
        QTRY_VERIFY_WITH_TIMEOUT(w.lastRun()->frameIndex > seqConverged, 20000);
        const double calibratedMsv = msvOf(w.lastRun()->frame);
        QVERIFY2(std::abs(calibratedMsv - target.msvTarget) <= target.msvTolerance, qPrintable(QString::number(calibratedMsv)));
        screenshot(w, "live-camera-calibrated.png");

        // 3. Fine-tune by hand: exposure typed into its spin box, read back, used by the sensor.
        QSpinBox* exposure = panel->spinBox(CameraFeatureId::Exposure);
        QVERIFY(exposure);
        const int handSet = exposure->value() + 37;
        exposure->selectAll();
        QTest::keyClicks(exposure, QString::number(handSet));
        QTest::keyClick(exposure, Qt::Key_Enter);
        CameraFeature readBack;
        QVERIFY(!camera->readFeature(CameraFeatureId::Exposure, readBack));
        QCOMPARE(readBack.value, handSet);
        QCOMPARE(exposure->value(), handSet);
        QCOMPARE(panel->mismatchText(CameraFeatureId::Exposure), QString());
        QTRY_COMPARE_WITH_TIMEOUT(camera->effectiveSettings().exposure, handSet, 20000);
        QApplication::focusWidget()->clearFocus();  // back to the panes: in a text field Space types

        // 4. Record to a new session folder chosen in the dialog, N frames, Stop.
        QTemporaryDir dir;
        const QString folder = dir.path() + "/session";
        QVERIFY(QDir().mkpath(folder));
        const int n = 20;
        answerNextFolderDialog(folder);
        w.findChild<QAction*>("cameraRecord")->trigger();
        QVERIFY(w.live()->isRecording());
        w.activateWindow();  // the dialog had it: the window's keys need it back
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTRY_VERIFY_WITH_TIMEOUT(w.live()->recorder()->status().written >= n, 30000);
        QTRY_VERIFY(w.live()->recordBar()->text().contains("frames written"));
        screenshot(w, "live-camera-recording.png");
        QTest::mouseClick(w.live()->recordBar()->stopButton(), Qt::LeftButton);
        QVERIFY(!w.live()->isRecording());
        QTest::keyClick(&w, Qt::Key_Space);  // pause: the ring keeps what the live view showed
        QVERIFY(!w.navigator()->isPlaying());
        const QRegularExpressionMatch m = QRegularExpression("(\\d+) frames written").match(w.notices()->text());
        QVERIFY2(m.hasMatch(), qPrintable(w.notices()->text()));
        const int written = m.captured(1).toInt();
        QVERIFY(written >= n);
        std::vector<cv::Mat> shown;  // the live view's frames, oldest first
        for (int p = 0; p < ring->size(); ++p) {
            Frame f;
            QVERIFY(ring->find(ring->seqAt(p), f));
            shown.push_back(f.image.clone());
        }
        SessionOpen recorded = SessionReader::open(folder.toStdString());
        QVERIFY(recorded.ok());
        QCOMPARE(recorded.reader->frameCount(), written);
        QCOMPARE(QDir(folder + "/frames").entryList({"*.png"}, QDir::Files).size(), written);
        QCOMPARE(recorded.reader->info().camera.exposure, handSet);  // the settings snapshot
        QVERIFY(recorded.reader->info().complete.value_or(false));

        // 5. Open the session in the window and step through it frame by frame.
        if (w.document()->isDirty()) answerNextMessageBox(QMessageBox::Discard, nullptr);
        QVERIFY(w.openSource(folder));
        w.activateWindow();  // after the message box
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(!w.live()->isOpen());
        QCOMPARE(w.navigator()->frameCount(), written);
        int lastMatch = -1;
        for (int k = 0; k < written; ++k) {
            if (k > 0) QTest::keyClick(&w, Qt::Key_Right);
            QVERIFY2(waitForFrame(w, k), qPrintable(QString("frame %1").arg(k)));
            QCOMPARE(w.navigator()->current(), k);
            const cv::Mat onDisk = cv::imread(recorded.reader->framePath(k), cv::IMREAD_COLOR);
            QVERIFY(sameImage(w.lastRun()->frame, onDisk));
            // ... and the frame the live view had, in recording order (a frame the recorder
            // dropped would be skipped, never reordered).
            int at = lastMatch + 1;
            while (at < int(shown.size()) && !sameImage(shown[std::size_t(at)], onDisk)) ++at;
            QVERIFY2(at < int(shown.size()), qPrintable(QString("frame %1 is not one the live view showed").arg(k)));
            lastMatch = at;
            if (k == written / 2) screenshot(w, "live-camera-replay.png");
        }
        QTest::keyClick(&w, Qt::Key_Left);
        QVERIFY(waitForFrame(w, written - 2));
    }
};

QTEST_MAIN(LiveDoneWhenTest)
#include "app_live_done_when_test.moc"
