// omnitune-calibrate as a user runs it: the real binary (path from CMake) through QProcess on
// the demo session and on files written here; exit codes, the one-line reasons, the configs it
// writes and the backups it keeps.
#include "calib/fit/RimFit.h"
#include "core/ConfigParser.h"

#include <opencv2/imgcodecs.hpp>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

namespace {

const QString kCalibrate = QStringLiteral(OMNITUNE_CALIBRATE);
const QString kDemo = QStringLiteral(OMNITUNE_SOURCE_DIR) + "/sessions/demo";
constexpr int kTimeoutMs = 10 * 60 * 1000;  // a hang fails, a slow sanitizer build does not

struct Run {
    int exitCode = -1;
    bool cleanExit = false;
    QString out;
    QString err;
    QString describe() const { return "\n  exit " + QString::number(exitCode) + "\n  stderr: " + err + "\n  stdout: " + out; }
    QStringList errLines() const { return err.split('\n', Qt::SkipEmptyParts); }
};

Run calibrate(const QStringList& args)
{
    QProcess p;
    p.start(kCalibrate, args);
    Run r;
    if (!p.waitForStarted(kTimeoutMs) || !p.waitForFinished(kTimeoutMs)) {
        p.kill();
        p.waitForFinished(kTimeoutMs);
        r.err = "did not run or finish: " + p.errorString();
        return r;
    }
    r.cleanExit = p.exitStatus() == QProcess::NormalExit;
    r.exitCode = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

void writeText(const QString& path, const QByteArray& text)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

}  // namespace

class AppCalibrateTest : public QObject {
    Q_OBJECT

private slots:
    void help()
    {
        const Run r = calibrate({"--help"});
        QVERIFY2(r.cleanExit && r.exitCode == 0, qPrintable(r.describe()));
        for (const char* word : {"rim", "distance-map", "ball-model", "--points", "--out"})
            QVERIFY2(r.out.contains(word), word);
        QCOMPARE(calibrate({"rim", "--help"}).exitCode, 0);
    }

    void badCommandLines_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("reason");
        QTest::newRow("no subcommand") << QStringList{} << "no subcommand";
        QTest::newRow("unknown subcommand") << QStringList{"centre", "--out", "x.yml"} << "unknown subcommand 'centre'";
        QTest::newRow("no --out") << QStringList{"rim", "--input", kDemo} << "--out OUT.yml is required";
        QTest::newRow("unknown option") << QStringList{"rim", "--frame", "3"} << "unknown option '--frame'";
        QTest::newRow("rim without input") << QStringList{"rim", "--out", "x.yml"} << "rim needs --input";
        QTest::newRow("bad --frames") << QStringList{"rim", "--input", kDemo, "--out", "x.yml", "--frames", "0"} << "--frames must be";
        QTest::newRow("missing input") << QStringList{"rim", "--input", "/nonexistent/s", "--out", "x.yml"} << "/nonexistent/s";
        QTest::newRow("bad height") << QStringList{"distance-map", "--points", "p.csv", "--out", "x.yml", "--height", "-1"}
                                    << "--height must be a positive number";
        QTest::newRow("no points") << QStringList{"distance-map", "--out", "x.yml"} << "needs --points";
        QTest::newRow("missing points file") << QStringList{"distance-map", "--points", "/nonexistent/p.csv", "--out", "x.yml"}
                                             << "/nonexistent/p.csv: cannot be read";
    }

    void badCommandLines()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, reason);
        const Run r = calibrate(args);
        QVERIFY2(r.cleanExit && r.exitCode == 1, qPrintable(r.describe()));
        QCOMPARE(r.errLines().size(), 1);
        QVERIFY2(r.err.startsWith("omnitune-calibrate: ") && r.err.contains(reason), qPrintable(r.describe()));
    }

    // On the demo: the geometry it was rendered with comes back (tolerances as in calib/fit).
    void rimOnDemoWritesGeometryWithBackup()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out.yml");
        QVERIFY(QFile::copy(kDemo + "/config.yml", out));
        const Run r = calibrate({"rim", "--input", kDemo, "--out", out});
        QVERIFY2(r.cleanExit && r.exitCode == 0, qPrintable(r.describe()));
        for (const char* word : {"centre", "mirror rim", "residual RMS", "outer radius", "inner radius", "wrote"})
            QVERIFY2(r.out.contains(word), qPrintable(r.describe()));
        QVERIFY2(r.out.contains(out + ".bak keeps the file from before OmniTune first saved over it"), qPrintable(r.out));
        QVERIFY(QFileInfo::exists(out + ".bak"));
        const omnitune::ConfigLoad load = omnitune::loadConfig(out.toStdString());
        QVERIFY(load.ok());
        const auto& g = load.config.geometry;
        QVERIFY2(std::hypot(g.centerX - 320, g.centerY - 240) < 1.0, qPrintable(r.out));
        // 240 with the former 4 px rim margin; RimFitOptions::marginPx widens the ring by the difference.
        QVERIFY2(std::abs(g.outerRadius - (4.0 - omnitune::RimFitOptions{}.marginPx) - 240) < 3.0, qPrintable(r.out));
        QVERIFY2(std::abs(g.innerRadius - 50) < 3.0, qPrintable(r.out));
        QCOMPARE(g.imageWidth, 640);
    }

    void ballModelOnDemo()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out.yml");
        const Run r = calibrate({"ball-model", "--input", kDemo, "--out", out});
        QVERIFY2(r.cleanExit && r.exitCode == 0, qPrintable(r.describe()));
        QVERIFY2(r.out.contains("r(d) = ") && r.out.contains("residual RMS"), qPrintable(r.out));
        QVERIFY(!QFileInfo::exists(out + ".bak"));  // nothing to back up
        const omnitune::ConfigLoad load = omnitune::loadConfig(out.toStdString());
        QVERIFY(load.ok());
        const omnitune::BallModel fitted(load.config.ball);
        const omnitune::BallModel original(omnitune::BallModelOptions{});  // the demo uses the defaults
        for (double d = 80; d <= 220; d += 20) QVERIFY(std::abs(fitted.radiusAt(d) - original.radiusAt(d)) < 0.3);
    }

    // A ball laid out at measured ground distances, its radius read off the image: the
    // distances go through the config's distance map.
    void ballModelFromSamplesFile()
    {
        QTemporaryDir dir;
        const omnitune::ConfigLoad demo = omnitune::loadConfig((kDemo + "/config.yml").toStdString());
        QVERIFY(demo.ok());
        const omnitune::DistanceMap map(demo.config.distanceMap);
        const omnitune::BallModel truth(demo.config.ball);
        QByteArray csv = "distance_m,radius_px\n";
        for (int i = 0; i < 12; ++i) {
            const double m = 0.8 + 0.2 * i;
            csv += QByteArray::number(m) + "," + QByteArray::number(truth.radiusAt(map.ballPixels(m)), 'f', 4) + "\n";
        }
        writeText(dir.filePath("s.csv"), csv);
        const QString out = dir.filePath("out.yml");
        const Run r = calibrate({"ball-model", "--samples", dir.filePath("s.csv"), "--config", kDemo + "/config.yml", "--out", out});
        QVERIFY2(r.cleanExit && r.exitCode == 0, qPrintable(r.describe()));
        QVERIFY2(r.out.contains("12 samples from"), qPrintable(r.out));
        const omnitune::ConfigLoad load = omnitune::loadConfig(out.toStdString());
        QVERIFY(load.ok());
        const omnitune::BallModel fitted(load.config.ball);
        for (double d = 115; d <= 195; d += 10) QVERIFY(std::abs(fitted.radiusAt(d) - truth.radiusAt(d)) < 0.05);

        // Without a config the ground distances have no map to go through.
        const Run refused = calibrate({"ball-model", "--samples", dir.filePath("s.csv"), "--out", out});
        QVERIFY2(refused.cleanExit && refused.exitCode == 1, qPrintable(refused.describe()));
        QVERIFY2(refused.err.contains("need the config's distance map"), qPrintable(refused.describe()));
    }

    void ballModelNeedsSessionAndCentre()
    {
        QTemporaryDir dir;
        cv::imwrite(dir.filePath("a.png").toStdString(), cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(0)));
        const Run r = calibrate({"ball-model", "--input", dir.path(), "--out", dir.filePath("o.yml")});
        QVERIFY2(r.cleanExit && r.exitCode == 1, qPrintable(r.describe()));
        QCOMPARE(r.errLines().size(), 1);
    }

    void distanceMapFromPoints()
    {
        QTemporaryDir dir;
        const QString points = dir.filePath("points.csv");
        QByteArray csv = "radius_px,distance_m\n";
        for (int r = 60; r <= 230; r += 10)
            csv += QByteArray::number(r) + "," + QByteArray::number(0.004 * r + 2.2e-7 * r * r * r, 'f', 4) + "\n";
        writeText(points, csv);
        const QString out = dir.filePath("out.yml");
        const Run r = calibrate({"distance-map", "--config", kDemo + "/config.yml", "--points", points, "--out", out,
                                 "--height", "0.62"});
        QVERIFY2(r.cleanExit && r.exitCode == 0, qPrintable(r.describe()));
        QVERIFY2(r.out.contains("residual RMS 0.0"), qPrintable(r.out));  // exact cubic: under a tenth of a cm
        const omnitune::ConfigLoad load = omnitune::loadConfig(out.toStdString());
        QVERIFY(load.ok());
        const omnitune::DistanceMap map(load.config.distanceMap);
        QVERIFY(std::abs(map.toGround(150) - (0.6 + 2.2e-7 * 150 * 150 * 150)) < 0.005);
        QCOMPARE(int(load.config.distanceMap.pixelRadii.size()), 16);
        QCOMPARE(load.config.distanceMap.viewpointHeight, 0.62);
    }

    void distanceMapRefusals_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::addColumn<QString>("reason");
        QTest::newRow("too few points") << QByteArray("radius_px,distance_m\n60,0.3\n100,0.8\n150,1.6\n200,3.0\n")
                                        << "needs at least 5 points";
        QTest::newRow("not monotone") << QByteArray("radius_px,distance_m\n60,0.3\n90,0.6\n120,1.0\n150,1.6\n180,2.5\n210,1.2\n")
                                      << "not monotone: it bends back at";
        QTest::newRow("no header") << QByteArray("60,0.3\n90,0.6\n") << "the first line must name the columns";
        QTest::newRow("image points without a config") << QByteArray("x,y,distance_m\n400,240,1\n")
                                                       << "needs the mirror centre";
    }

    void distanceMapRefusals()
    {
        QFETCH(QByteArray, csv);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        writeText(dir.filePath("p.csv"), csv);
        const QString out = dir.filePath("out.yml");
        const Run r = calibrate({"distance-map", "--points", dir.filePath("p.csv"), "--out", out});
        QVERIFY2(r.cleanExit && r.exitCode == 1, qPrintable(r.describe()));
        QVERIFY2(r.errLines().last().startsWith("omnitune-calibrate: ") && r.err.contains(reason), qPrintable(r.describe()));
        QVERIFY(!QFileInfo::exists(out));  // nothing written
    }

    void rimRefusesBlackFramesAndKeepsOut()
    {
        QTemporaryDir dir;
        QDir().mkpath(dir.filePath("frames"));
        for (int i = 0; i < 3; ++i)
            cv::imwrite(dir.filePath("frames/f" + QString::number(i) + ".png").toStdString(),
                        cv::Mat(480, 480, CV_8UC3, cv::Scalar::all(0)));
        const QString out = dir.filePath("out.yml");
        writeText(out, "previous");
        const Run r = calibrate({"rim", "--input", dir.filePath("frames"), "--out", out});
        QVERIFY2(r.cleanExit && r.exitCode == 1, qPrintable(r.describe()));
        QVERIFY2(r.errLines().last().contains("no contrast"), qPrintable(r.describe()));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("previous"));
        QVERIFY(!QFileInfo::exists(out + ".bak"));
    }

    // colours on a frame with a cyan-green carpet (outside the default green box): the config
    // it writes loads and its green holds the carpet's hue.
    void coloursWritesAConfigThatLoads()
    {
        QTemporaryDir dir;
        const QString frame = dir.filePath("cyan_green.png");
        cv::Mat img(480, 640, CV_8UC3, cv::Scalar(150, 160, 30));  // hue 88
        img(cv::Rect(150, 100, 300, 8)).setTo(cv::Scalar(235, 235, 235));  // a line
        QVERIFY(cv::imwrite(frame.toStdString(), img));
        const QString out = dir.filePath("out.yml");
        const Run r = calibrate({"colours", "--input", frame, "--config", kDemo + "/config.yml", "--out", out});
        QVERIFY2(r.cleanExit && r.exitCode == 0, qPrintable(r.describe()));
        for (const char* word : {"carpet   hue 88", "green", "white", "black", "wrote"})
            QVERIFY2(r.out.contains(word), qPrintable(r.describe()));
        const omnitune::ConfigLoad load = omnitune::loadConfig(out.toStdString());
        QVERIFY(load.ok());
        const auto& green = load.config.colors.classes[std::size_t(omnitune::ColorClass::Green) - 1].boxes.front();
        QVERIFY2(green.containsHue(88) && green.hMin > 70, qPrintable(r.out));
        QVERIFY(load.config.colors.blackRelative);
        QCOMPARE(load.config.geometry.imageWidth, 640);  // the rest kept

        // Without a config there is no geometry to sample: refused, nothing written.
        const QString none = dir.filePath("none.yml");
        const Run refused = calibrate({"colours", "--input", frame, "--out", none});
        QVERIFY2(refused.cleanExit && refused.exitCode == 1, qPrintable(refused.describe()));
        QVERIFY2(refused.err.contains("--config"), qPrintable(refused.describe()));
        QVERIFY(!QFileInfo::exists(none));
    }

    void rimFromOneFrameNeedsNoBody()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out.yml");
        const QString frame = kDemo + "/frames/000000.png";
        const Run a = calibrate({"rim", "--input", frame, "--out", out});
        QVERIFY2(a.cleanExit && a.exitCode == 1, qPrintable(a.describe()));
        QVERIFY2(a.errLines().last().contains("--no-body"), qPrintable(a.describe()));
        const Run b = calibrate({"rim", "--input", frame, "--out", out, "--no-body"});
        QVERIFY2(b.cleanExit && b.exitCode == 0, qPrintable(b.describe()));
        QVERIFY2(b.err.contains("starting from the defaults"), qPrintable(b.describe()));
        QVERIFY(QFileInfo::exists(out));
    }

    // The demo robot has no support rods: the auto-mask keeps its field and cuts out its body.
    void autoMaskOnDemo()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out.yml");
        const Run r = calibrate({"mask", "--auto", "--input", kDemo, "--out", out});
        QVERIFY2(r.cleanExit && r.exitCode == 0, qPrintable(r.describe()));
        QVERIFY2(r.out.contains("robot region(s)") && r.out.contains("mask.png"), qPrintable(r.out));
        const omnitune::ConfigLoad load = omnitune::loadConfig(out.toStdString());
        QVERIFY2(load.ok(), load.ok() ? "" : load.error->toString().c_str());
        QCOMPARE(QString::fromStdString(load.config.geometry.maskFile), QString("mask.png"));
        const cv::Mat mask = load.config.mask;
        QCOMPARE(mask.cols, 640);
        const auto& g = load.config.geometry;
        long field = 0, fieldKept = 0, body = 0, bodyCut = 0;
        for (int y = 0; y < mask.rows; ++y)
            for (int x = 0; x < mask.cols; ++x) {
                const double d = std::hypot(x - g.centerX, y - g.centerY);
                const bool kept = mask.at<std::uint8_t>(y, x) != 0;
                if (d > g.innerRadius + 6 && d < g.outerRadius - 6) ++field, fieldKept += kept;
                if (d < g.innerRadius - 6) ++body, bodyCut += !kept;
            }
        QVERIFY2(fieldKept > 0.97 * field, qPrintable(QString("%1 of %2 field pixels kept").arg(fieldKept).arg(field)));
        QVERIFY2(bodyCut > 0.9 * body, qPrintable(QString("%1 of %2 body pixels cut").arg(bodyCut).arg(body)));
    }

    // Issue 11: another team's mask, red rods on black (black = process), imported both ways.
    void importedMaskConventions()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("their-mask.png");
        cv::Mat theirs(480, 640, CV_8UC3, cv::Scalar(0, 0, 0));
        theirs.colRange(318, 323).setTo(cv::Scalar(0, 0, 255));  // a red rod through the centre
        QVERIFY(cv::imwrite(file.toStdString(), theirs));
        const QString out = dir.filePath("out.yml");
        const QString config = kDemo + "/config.yml";

        const Run wrong = calibrate({"mask", "--import", file, "--config", config, "--out", out});
        QVERIFY2(wrong.exitCode == 0, qPrintable(wrong.describe()));
        QVERIFY2(wrong.err.contains("leaves most of the ring out"), qPrintable(wrong.describe()));
        const omnitune::ConfigLoad reversed = omnitune::loadConfig(out.toStdString());
        QVERIFY(reversed.ok());
        bool warned = false;  // the loader says it too, every time the config is opened
        for (const auto& w : reversed.warnings) warned |= w.message.find("--process black") != std::string::npos;
        QVERIFY(warned);

        const Run right = calibrate({"mask", "--import", file, "--process", "black", "--config", config, "--out", out});
        QVERIFY2(right.exitCode == 0 && !right.err.contains("leaves most"), qPrintable(right.describe()));
        QVERIFY2(right.out.contains("black = process") && right.out.contains("% of the ring"), qPrintable(right.out));
        const omnitune::ConfigLoad load = omnitune::loadConfig(out.toStdString());
        QVERIFY(load.ok());
        QVERIFY(load.warnings.empty());
        QCOMPARE(int(load.config.mask.at<std::uint8_t>(100, 320)), 0);    // the rod: not processed
        QCOMPARE(int(load.config.mask.at<std::uint8_t>(100, 200)), 255);  // the field

        const Run bad = calibrate({"mask", "--import", file, "--process", "red", "--config", config, "--out", out});
        QVERIFY2(bad.exitCode == 1 && bad.err.contains("--process must be white or black"), qPrintable(bad.describe()));
        cv::Mat small(100, 100, CV_8UC1, cv::Scalar(255));
        QVERIFY(cv::imwrite(dir.filePath("small.png").toStdString(), small));
        const Run size = calibrate({"mask", "--import", dir.filePath("small.png"), "--config", config, "--out", out});
        QVERIFY2(size.exitCode == 1 && size.err.contains("100x100") && size.err.contains("640x480"), qPrintable(size.describe()));
    }

    void autoMaskRefusals()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out.yml");
        const Run noAuto = calibrate({"mask", "--input", kDemo, "--out", out});
        QVERIFY2(noAuto.exitCode == 1 && noAuto.err.contains("mask needs --auto (from frames) or --import"), qPrintable(noAuto.describe()));
        const Run one = calibrate({"mask", "--auto", "--input", kDemo + "/frames/000000.png", "--config",
                                   kDemo + "/config.yml", "--out", out});
        QVERIFY2(one.exitCode == 1 && one.err.contains("drives or turns"), qPrintable(one.describe()));
        QVERIFY(!QFileInfo::exists(out));
    }
};

QTEST_GUILESS_MAIN(AppCalibrateTest)
#include "app_calibrate_test.moc"
