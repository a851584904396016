// omnitune-camera as a user runs it, through QProcess: --list and the real sources on a machine
// without cameras (a clear one-line refusal, no crash, no hang), --auto on the simulated camera
// from bad starts (last line "converged: ...", exit 0) and with a feature held at its limit
// ("not converged: ...", exit 1), --set with read-back, --config applying the camera section,
// --out writing the settings atomically with a backup, --record writing a session whose
// session.yml holds the settings.
#include "calib/camera/CameraCatalog.h"
#include "calib/session/SessionReader.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "ToolRun.h"

using namespace tooltest;
using namespace omnitune;

namespace {

const QString kCamera = QStringLiteral(OMNITUNE_CAMERA);

QStringList outLines(const Run& r)
{
    QStringList lines = QString::fromUtf8(r.out).split('\n');
    while (!lines.isEmpty() && lines.last().trimmed().isEmpty()) lines.removeLast();
    return lines;
}

// "msv=2.47" -> 2.47 from a line; NaN when absent.
double field(const QString& line, const QString& name)
{
    const auto m = QRegularExpression("\\b" + name + "=(-?[0-9.]+)").match(line);
    return m.hasMatch() ? m.captured(1).toDouble() : std::nan("");
}

bool noCameras() { return listCameras().cameras.empty(); }

}  // namespace

class CameraToolTest : public QObject {
    Q_OBJECT

private slots:
    void helpNamesEveryOption()
    {
        const Run r = runTool(kCamera, {"--help"});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        for (const char* opt : {"--source", "--list", "--set", "--auto", "--record", "--seconds", "--config", "--out", "--start"})
            QVERIFY2(r.out.contains(opt), opt);
    }

    void listSaysNoneFound()
    {
        if (!noCameras()) QSKIP("a camera is connected");
        const Run r = runTool(kCamera, {"--list"});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        QVERIFY2(r.out.startsWith("no camera found\n"), r.out.constData());
        QVERIFY(r.out.contains("dc1394:"));
        QVERIFY(r.out.contains("v4l2:"));
        QVERIFY(r.out.contains("simulated"));
    }

    void listOfTheSimulatedCameraShowsItsFeatures()
    {
        const Run r = runTool(kCamera, {"--source", "simulated", "--list"});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        QVERIFY2(r.out.contains("exposure 300 (0..4095, manual only)"), r.out.constData());
        QVERIFY(r.out.contains("white_balance_red"));
    }

    void realSourcesWithoutDeviceRefuseCleanly_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        QTest::newRow("dc1394") << QStringList{"--source", "dc1394"} << "dc1394";
        QTest::newRow("dc1394 guid") << QStringList{"--source", "dc1394:0x00b09d0100a01a9a", "--auto"} << "dc1394";
        QTest::newRow("v4l2 device") << QStringList{"--source", "v4l2:/dev/video-omnitune-none", "--list"}
                                     << "/dev/video-omnitune-none";
        QTest::newRow("first found") << QStringList{"--auto"} << "no camera found";
        QTest::newRow("unknown") << QStringList{"--source", "usb"} << "unknown camera source 'usb'";
    }

    void realSourcesWithoutDeviceRefuseCleanly()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        if (!noCameras() && says != "unknown camera source 'usb'" && !says.startsWith("/dev")) QSKIP("a camera is connected");
        const Run r = runTool(kCamera, args);
        QVERIFY2(r.refused(), qPrintable(r.describe()));
        QCOMPARE(r.errLines().size(), 1);
        QVERIFY2(r.errLines().first().startsWith("omnitune-camera: ") && r.errLines().first().contains(says),
                 qPrintable(r.describe()));
    }

    void autoConvergesFromBadStarts_data()
    {
        QTest::addColumn<QString>("start");
        QTest::newRow("dark") << "dark";
        QTest::newRow("bright") << "bright";
        QTest::newRow("tinted") << "tinted";
    }

    void autoConvergesFromBadStarts()
    {
        QFETCH(QString, start);
        const Run r = runTool(kCamera, {"--source", "simulated", "--start", start, "--auto"});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        const QStringList lines = outLines(r);
        QVERIFY(lines.size() >= 2);
        const QString last = lines.last();
        QVERIFY2(last.startsWith("converged: msv="), qPrintable(last));
        QVERIFY(std::abs(field(last, "msv") - 2.5) <= 0.3);
        QVERIFY(std::abs(field(last, "wb_u") - 128) <= 3);
        QVERIFY(std::abs(field(last, "wb_v") - 128) <= 3);
        const int iterations = int(field(last, "iterations"));
        QVERIFY(iterations >= 1 && iterations <= 30);
        QCOMPARE(lines.size() - 1, iterations);  // one line per iteration, then the verdict
        QVERIFY(lines.first().startsWith("iteration 1: msv="));
        QVERIFY(std::abs(field(lines.first(), "msv") - 2.5) > 0.3 || std::abs(field(lines.first(), "wb_v") - 128) > 10);
    }

    void autoAtALimitIsNotConverged()
    {
        QTemporaryDir tmp;
        Config c;
        c.cameraAuto.exposureMax = 80;
        c.cameraAuto.gainMax = 100;
        const std::string path = tmp.filePath("limits.yml").toStdString();
        QVERIFY(!saveConfig(c, path, false));
        const Run r = runTool(kCamera, {"--source", "simulated", "--start", "dark", "--auto", "--config",
                                        QString::fromStdString(path), "--out", tmp.filePath("out.yml")});
        QVERIFY2(r.exitedWith(1), qPrintable(r.describe()));
        const QString last = outLines(r).last();
        QVERIFY2(last.startsWith("not converged: exposure and gain at their upper limits"), qPrintable(last));
        QVERIFY(!QFile::exists(tmp.filePath("out.yml")));  // nothing written from a failed calibration
    }

    void setReadsBackAndOutWritesTheConfig()
    {
        QTemporaryDir tmp;
        const QString out = tmp.filePath("camera.yml");
        Run r = runTool(kCamera, {"--source", "simulated", "--set", "exposure=410", "--set", "wb_u=600", "--out", out});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        QVERIFY(r.out.contains("exposure = 410\n"));
        QVERIFY(r.out.contains("white_balance_blue = 600\n"));
        ConfigLoad load = loadConfig(out.toStdString());
        QVERIFY2(load.ok(), load.error ? load.error->toString().c_str() : "");
        QCOMPARE(load.config.camera.exposure, 410);
        QCOMPARE(load.config.camera.whiteBalanceBlue, 600);
        QCOMPARE(load.config.camera.source, std::string("simulated"));

        // --config applies its camera section; --out over an existing file keeps a backup.
        r = runTool(kCamera, {"--config", out, "--set", "gain=300", "--out", out});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        QVERIFY2(r.out.contains("applied the camera section of " + out.toUtf8() + ": exposure=410 gain=200"),
                 r.out.constData());
        QVERIFY(QFile::exists(out + ".bak"));
        load = loadConfig(out.toStdString());
        QCOMPARE(load.config.camera.gain, 300);
        QCOMPARE(load.config.camera.exposure, 410);
        QCOMPARE(loadConfig((out + ".bak").toStdString()).config.camera.gain, 200);
    }

    void badSetsAreRefused_data()
    {
        QTest::addColumn<QString>("set");
        QTest::addColumn<QString>("says");
        QTest::newRow("range") << "gain=5000" << "gain 5000 is outside its range 0..1023";
        QTest::newRow("unknown") << "shine=3" << "unknown feature 'shine'";
        QTest::newRow("unsupported") << "gamma=3" << "has no gamma";
        QTest::newRow("not a number") << "gain=lots" << "'lots' is not a whole number";
        QTest::newRow("no value") << "gain" << "expected FEATURE=VALUE";
    }

    void badSetsAreRefused()
    {
        QFETCH(QString, set);
        QFETCH(QString, says);
        const Run r = runTool(kCamera, {"--source", "simulated", "--set", set});
        QVERIFY2(r.refused(), qPrintable(r.describe()));
        QVERIFY2(r.errLines().size() == 1 && r.errLines().first().contains(says), qPrintable(r.describe()));
    }

    void recordWritesASessionWithTheSettings()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath("rec");
        const Run r = runTool(kCamera, {"--source", "simulated", "--set", "exposure=350", "--record", dir, "--seconds", "0.5"});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        QVERIFY2(r.out.contains("recorded 15 frames to " + dir.toUtf8() + " (0 dropped)"), r.out.constData());
        const SessionOpen s = SessionReader::open(dir.toStdString());
        QVERIFY(s.ok());
        QCOMPARE(s.reader->frameCount(), 15);
        QCOMPARE(s.reader->info().camera.exposure, 350);
        QCOMPARE(s.reader->info().complete, std::optional<bool>(true));
        QVERIFY(QString::fromStdString(s.reader->info().notes).contains("simulated camera"));

        // A second recording into the same folder is refused, the first kept.
        const Run again = runTool(kCamera, {"--source", "simulated", "--record", dir, "--seconds", "0.2"});
        QVERIFY2(again.refused(), qPrintable(again.describe()));
        QCOMPARE(SessionReader::open(dir.toStdString()).reader->frameCount(), 15);
    }

    void argumentErrorsNameTheArgument()
    {
        Run r = runTool(kCamera, {"--source", "simulated", "--seconds", "3"});
        QVERIFY(r.refused() && r.err.contains("--seconds goes with --record"));
        r = runTool(kCamera, {"--source", "simulated", "--start", "purple"});
        QVERIFY(r.refused() && r.err.contains("--start must be good, dark, bright or tinted"));
        r = runTool(kCamera, {"--source", "v4l2", "--start", "dark"});
        QVERIFY(r.refused() && r.err.contains("--start and --seed are for --source simulated"));
        r = runTool(kCamera, {"--config", "/nonexistent/c.yml", "--source", "simulated"});
        QVERIFY(r.refused() && r.err.contains("/nonexistent/c.yml"));
    }
};

QTEST_GUILESS_MAIN(CameraToolTest)
#include "app_camera_tool_test.moc"
