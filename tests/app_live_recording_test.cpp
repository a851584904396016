// Recording the live view into a session (issue 12): from the window (Camera > Record, the
// record bar, Stop) the session reopens with exactly the frames the notice says were written,
// the camera's settings in session.yml and the config in use; a recording whose process is
// killed (omnitune-camera --record, SIGKILL) keeps every frame it wrote and still opens; a disk
// below camera.record_min_free_mb stops the recording at once with a message naming the key.
#include "calib/session/SessionReader.h"
#include "calib/source/FrameSourceFactory.h"
#include "widgets/ConfigDocument.h"
#include "widgets/LiveController.h"
#include "widgets/NoticeBar.h"
#include "widgets/RecordBar.h"

#include "LiveTestSupport.h"

#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>

#include <csignal>

using namespace omnitune;
using namespace omnitune::testing;

namespace {
int pngCount(const QString& folder) { return QDir(folder + "/frames").entryList({"*.png"}, QDir::Files).size(); }
}  // namespace

class LiveRecordingTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { isolateRecoveryFiles(); }

    void recordsFromTheWindowAndReopens()
    {
        QTemporaryDir dir;
        const QString folder = dir.path() + "/run1";
        MainWindow w;
        QVERIFY(showActive(w));
        QVERIFY(openSimulatedCamera(w));
        QVERIFY(w.findChild<QAction*>("cameraRecord")->isEnabled());
        QCOMPARE(w.live()->startRecording(folder), QString());
        QVERIFY(w.live()->recordBar()->isVisible());
        QVERIFY(!w.findChild<QAction*>("cameraRecord")->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(w.live()->recorder()->status().written >= 12, 30000);
        QTRY_VERIFY(w.live()->recordBar()->text().contains("frames written"));
        QVERIFY(w.live()->recordBar()->text().contains("free"));
        QTest::mouseClick(w.live()->recordBar()->stopButton(), Qt::LeftButton);
        QVERIFY(!w.live()->isRecording());
        QVERIFY(!w.live()->recordBar()->isVisible());
        const QRegularExpressionMatch m = QRegularExpression("(\\d+) frames written, (\\d+) dropped").match(w.notices()->text());
        QVERIFY2(m.hasMatch(), qPrintable(w.notices()->text()));
        const int written = m.captured(1).toInt();
        QVERIFY(written >= 12);

        SessionOpen opened = SessionReader::open(folder.toStdString());
        QVERIFY2(opened.ok(), opened.error ? opened.error->toString().c_str() : "");
        const SessionReader& reader = *opened.reader;
        QCOMPARE(reader.frameCount(), written);
        QCOMPARE(pngCount(folder), written);
        QVERIFY(reader.info().complete.value_or(false));
        // The camera snapshot: the config's settings, written to the camera when it opened.
        QCOMPARE(reader.info().camera.exposure, w.document()->config().camera.exposure);
        QCOMPARE(reader.info().camera.gain, w.document()->config().camera.gain);
        QVERIFY(QString::fromStdString(reader.info().notes).contains("simulated camera"));
        QVERIFY(reader.hasConfig());  // replays with the config it was recorded under
        cv::Mat last;
        QVERIFY(!reader.readFrame(written - 1, last));
    }

    void aKilledRecordingKeepsItsFrames()
    {
        QTemporaryDir dir;
        const QString folder = dir.path() + "/killed";
        QProcess tool;
        tool.start(OMNITUNE_CAMERA, {"--source", "simulated", "--record", folder, "--seconds", "100000"});
        QVERIFY(tool.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(pngCount(folder) >= 4, 60000);
        ::kill(pid_t(tool.processId()), SIGKILL);
        QVERIFY(tool.waitForFinished());
        const int written = pngCount(folder);
        SourceOpen<FrameSource> opened = openFrameSource(folder.toStdString());
        QVERIFY2(opened.ok(), opened.error.c_str());
        QCOMPARE(opened.source->frameCount(), written);
        for (int i = 0; i < written; ++i) {
            Frame f;
            const auto err = opened.source->read(i, f);
            QVERIFY2(!err, err ? err->message.c_str() : "");
            QCOMPARE(f.image.size(), cv::Size(640, 480));
        }
    }

    void aNearlyFullDiskStopsTheRecordingAtOnce()
    {
        QTemporaryDir dir;
        const QString folder = dir.path() + "/full";
        MainWindow w;
        QVERIFY(showActive(w));
        QVERIFY(openSimulatedCamera(w));
        QVERIFY(!w.document()->setValue("camera.record_min_free_mb", ConfigValue(100000000)));  // 100 TB
        QCOMPARE(w.live()->startRecording(folder), QString());
        QTRY_VERIFY_WITH_TIMEOUT(!w.live()->isRecording(), 20000);
        const QString notice = w.notices()->text();
        QVERIFY2(notice.contains("recording stopped") && notice.contains("camera.record_min_free_mb")
                     && notice.contains("0 frames written"),
                 qPrintable(notice));
        QVERIFY(!w.live()->recordBar()->isVisible());
        QCOMPARE(pngCount(folder), 0);
        QVERIFY(w.navigator());  // the live view goes on
        const int seq = w.live()->replay()->newestSeq();
        QTRY_VERIFY_WITH_TIMEOUT(w.live()->replay()->newestSeq() > seq, 20000);
    }
};

QTEST_MAIN(LiveRecordingTest)
#include "app_live_recording_test.moc"
