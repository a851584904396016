// The command-line tools against full disks, unwritable folders, outputs aimed at their own
// inputs, sessions naming configs they should not, stray frames and truth no frame can hold
// (issue 14). Each case drives the real binaries and checks the exit status, the one-line
// reason on stderr, and that every file the user had is still as it was.
#include "calib/session/SessionReader.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QRegularExpression>
#include <QtTest>

#include "ToolRun.h"

#include <filesystem>

namespace fs = std::filesystem;
using namespace tooltest;
using namespace omnitune;

namespace {

const QString kSim = QStringLiteral(OMNITUNE_SIM);
const QString kDetect = QStringLiteral(OMNITUNE_DETECT);
const QString kEval = QStringLiteral(OMNITUNE_EVAL);

constexpr int kFrames = 6;
// A disk that holds one 512-byte block per file, and write() failing with EFBIG instead of
// the signal killing the tool.
const QString kTinyDisk = QStringLiteral("trap '' XFSZ; ulimit -f 1;");

bool copyTree(const QString& from, const QString& to)
{
    std::error_code ec;
    fs::copy(from.toStdString(), to.toStdString(), fs::copy_options::recursive, ec);
    return !ec;
}

bool contains(const QByteArray& text, const QStringList& parts)
{
    for (const QString& p : parts)
        if (!QString::fromUtf8(text).contains(p)) return false;
    return true;
}

// Replaces (or adds) one top-level key of a session's session.yml.
bool setInfoKey(const QString& session, const QString& key, const QString& value)
{
    const QString path = session + "/session.yml";
    QStringList lines = QString::fromUtf8(readBytes(path)).split('\n');
    bool found = false;
    for (QString& line : lines)
        if (line.startsWith(key + ":")) {
            line = key + ": " + value;
            found = true;
        }
    if (!found) lines.insert(lines.size() - 1, key + ": " + value);
    return writeBytes(path, lines.join('\n').toUtf8());
}

}  // namespace

class ToolsRobustnessTest : public QObject {
    Q_OBJECT

private:
    QTemporaryDir tmp_;
    QString session_;  // kFrames frames with truth.csv and config.yml

    QString path(const QString& name) const { return tmp_.filePath(name); }
    // A copy of the session to damage.
    QString copyOfSession(const QString& name)
    {
        const QString dir = path(name);
        if (!copyTree(session_, dir)) qFatal("cannot copy the session");
        return dir;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(tmp_.isValid());
        session_ = path("tour");
        const Run sim = runTool(kSim, {"--out", session_, "--frames", QString::number(kFrames)});
        QVERIFY2(sim.exitedWith(0), qPrintable(sim.describe()));
    }

    // Issue 13 / defect 7: omnitune-sim closes what it records.
    void simMarksTheSessionComplete()
    {
        QVERIFY2(readBytes(session_ + "/session.yml").contains("\ncomplete: true"), readBytes(session_ + "/session.yml"));
    }

    // Defect 7: a recording killed mid-way (here omnitune-sim, killed once it wrote frames past
    // the first session.yml rewrites) says so when opened.
    void killedRecordingReadsAsInterrupted()
    {
        const QString dir = path("killed");
        QProcess sim;
        sim.start(kSim, {"--out", dir, "--frames", "100000", "--compression", "0"});
        QVERIFY(sim.waitForStarted(kTimeoutMs));
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(dir + "/frames/000031.png"), kTimeoutMs);
        sim.kill();
        QVERIFY(sim.waitForFinished(kTimeoutMs));
        const SessionOpen opened = SessionReader::open(dir.toStdString());
        QVERIFY(opened.ok());
        bool said = false;
        QString all;
        for (const SessionIssue& w : opened.reader->warnings()) {
            all += QString::fromStdString(w.toString()) + "\n";
            said = said || (w.key == "complete" && w.message.find("interrupted") != std::string::npos);
        }
        QVERIFY2(said, qPrintable("no word of the interruption:\n" + all));
        QVERIFY(opened.reader->frameCount() >= 31);
    }

    // Defect 2: a full disk is a failure naming the file and the OS reason, never exit 0 with
    // an empty CSV; a previous file of that name is kept.
    void detectReportsAFullDisk_data()
    {
        QTest::addColumn<QString>("out");     // --out; "" writes to standard output
        QTest::addColumn<QString>("prefix");  // shell prefix
        QTest::addColumn<QString>("reason");  // strerror text
        QTest::newRow("file too large (ulimit -f)") << "@T/kept.csv" << kTinyDisk << "File too large";
        QTest::newRow("/dev/full") << "/dev/full" << "" << "No space left on device";
        QTest::newRow("standard output on /dev/full") << "" << "exec >/dev/full;" << "No space left on device";
    }

    void detectReportsAFullDisk()
    {
        QFETCH(QString, out);
        QFETCH(QString, prefix);
        QFETCH(QString, reason);
        out.replace("@T", tmp_.path());
        const QByteArray before = "the previous results, kept\n";
        if (out.startsWith(tmp_.path())) QVERIFY(writeBytes(out, before));
        QStringList args{"--input", session_};
        if (!out.isEmpty()) args << "--out" << out;
        const Run r = runTool(kDetect, args, prefix);
        QVERIFY2(r.refused(), qPrintable("a full disk passed for success" + r.describe()));
        const QString named = out.isEmpty() ? QString("standard output") : out;
        QVERIFY2(contains(r.errLines().value(r.errLines().size() - 1).toUtf8(), {"omnitune-detect: ", named, reason}),
                 qPrintable(r.describe()));
        if (out.startsWith(tmp_.path())) {
            QCOMPARE(readBytes(out), before);
            QCOMPARE(QDir(tmp_.path()).entryList({"kept.csv.tmp*"}, QDir::Files), QStringList());
        }
    }

    // Defect 2: eval's table on a full disk is a failure too.
    void evalReportsAFullDisk()
    {
        const Run r = runTool(kEval, {"--session", session_}, "exec >/dev/full;");
        QVERIFY2(r.refused(), qPrintable("a table lost to a full disk passed for success" + r.describe()));
        QVERIFY2(contains(r.err, {"standard output", "No space left on device"}), qPrintable(r.describe()));
    }

    // Defect 2: stage images into a folder nothing can be written to (as root too: /proc).
    void detectReportsUnwritableStages()
    {
        const Run r = runTool(kDetect, {"--input", session_, "--out", path("stages.csv"), "--save-stages", "/proc"});
        QVERIFY2(r.refused(), qPrintable("unwritten stage images passed for success" + r.describe()));
        QVERIFY2(contains(r.err, {"/proc/000000_acquired.png"}), qPrintable(r.describe()));
        QVERIFY2(!QFile::exists(path("stages.csv")), "a failed run left its CSV behind");
    }

    // Defect 9: --out onto any file the run reads is refused, and the file is unchanged.
    void detectRefusesToOverwriteItsInput_data()
    {
        QTest::addColumn<QString>("target");  // @S: the session copy, @T: scratch
        QTest::addColumn<QStringList>("extra");
        QTest::newRow("the session's truth.csv") << "@S/truth.csv" << QStringList{};
        QTest::newRow("the session's config.yml") << "@S/config.yml" << QStringList{};
        QTest::newRow("session.yml") << "@S/session.yml" << QStringList{};
        QTest::newRow("a frame") << "@S/frames/000002.png" << QStringList{};
        QTest::newRow("the config's mask") << "@S/mask.png" << QStringList{};
        QTest::newRow("truth.csv through a link") << "@T/link-to-truth.csv" << QStringList{};
        QTest::newRow("--config given elsewhere") << "@T/other.yml" << QStringList{"--config", "@T/other.yml"};
        QTest::newRow("an image of a glob") << "@S/frames/000003.png" << QStringList{"--input", "@S/frames/*.png",
                                                                                  "--config", "@S/config.yml"};
    }

    void detectRefusesToOverwriteItsInput()
    {
        QFETCH(QString, target);
        QFETCH(QStringList, extra);
        const QString s = copyOfSession(QString("input-%1").arg(QTest::currentDataTag()).replace(' ', '_'));
        // The session's config reads a mask (all white: every pixel processed).
        QVERIFY(cv::imwrite((s + "/mask.png").toStdString(), cv::Mat(480, 640, CV_8UC1, cv::Scalar(255))));
        QString config = QString::fromUtf8(readBytes(s + "/config.yml"));
        QVERIFY(config.contains("mask_file: \"\""));
        QVERIFY(writeBytes(s + "/config.yml", config.replace("mask_file: \"\"", "mask_file: \"mask.png\"").toUtf8()));
        QFile::remove(path("link-to-truth.csv"));
        fs::create_hard_link((s + "/truth.csv").toStdString(), path("link-to-truth.csv").toStdString());
        QVERIFY(QFile::copy(session_ + "/config.yml", path("other.yml")) || QFile::exists(path("other.yml")));
        auto expand = [&](QString x) { return x.replace("@S", s).replace("@T", tmp_.path()); };
        target = expand(target);
        const QByteArray before = readBytes(target);
        QVERIFY(!before.isEmpty());
        QStringList args = extra.contains("--input") ? QStringList{} : QStringList{"--input", s};
        for (const QString& a : extra) args << expand(a);
        args << "--out" << target;
        const Run r = runTool(kDetect, args);
        QVERIFY2(r.refused(), qPrintable(r.describe()));
        QCOMPARE(r.errLines().size(), 1);
        QVERIFY2(contains(r.err, {target, "refusing to overwrite"}), qPrintable(r.describe()));
        QVERIFY2(readBytes(target) == before, qPrintable(target + " was changed"));
    }

    // Defect 6: detect and eval run with the config session.yml names, as the window does.
    void toolsUseTheConfigTheSessionNames()
    {
        const QString s = copyOfSession("named-config");
        // config.yml runs the specific Hough, the config session.yml names OpenCV's.
        QString config = QString::fromUtf8(readBytes(s + "/config.yml"));
        const QRegularExpression method(R"(method: "?combined"?)");  // the writer quotes choices
        QVERIFY(config.contains(method));
        QVERIFY(writeBytes(s + "/config.yml", QString(config).replace(method, "method: specific").toUtf8()));
        QVERIFY(writeBytes(s + "/tuned.yml", QString(config).replace(method, "method: opencv").toUtf8()));
        QVERIFY(setInfoKey(s, "config_file", "\"tuned.yml\""));

        const Run eval = runTool(kEval, {"--session", s, "--format", "csv"});
        QVERIFY2(eval.exitedWith(0), qPrintable(eval.describe()));
        const Csv table = parseCsv(eval.out);
        QCOMPARE(table.rows.size(), 1);
        QCOMPARE(table.at(0, "algorithm"), QString("opencv"));

        const Run detect = runTool(kDetect, {"--input", s});
        QVERIFY2(detect.exitedWith(0), qPrintable(detect.describe()));
        const Csv csv = parseCsv(detect.out);
        int opencv = 0;
        for (int i = 0; i < csv.rows.size(); ++i) {
            QVERIFY2(csv.at(i, "source") != "specific", qPrintable("frame " + csv.at(i, "frame") + " ran config.yml"));
            opencv += csv.at(i, "source") == "opencv";
        }
        QVERIFY(opencv > 0);
    }

    // Defect 6: a session may only name a file inside its folder; the tools say so and stop
    // rather than run with config.yml or read /etc/passwd.
    void toolsRefuseAConfigOutsideTheSession_data()
    {
        QTest::addColumn<QString>("configFile");
        QTest::addColumn<QString>("tool");
        QTest::newRow("detect, /etc/passwd") << "/etc/passwd" << "detect";
        QTest::newRow("eval, /etc/passwd") << "/etc/passwd" << "eval";
        QTest::newRow("detect, ../x.yml") << "../x.yml" << "detect";
        QTest::newRow("eval, ../x.yml") << "../x.yml" << "eval";
    }

    void toolsRefuseAConfigOutsideTheSession()
    {
        QFETCH(QString, configFile);
        QFETCH(QString, tool);
        const QString s = copyOfSession(QString("outside-%1").arg(QTest::currentDataTag()).replace(' ', '_').replace('/', '_'));
        QVERIFY(QFile::copy(s + "/config.yml", path("x.yml")) || QFile::exists(path("x.yml")));
        QVERIFY(setInfoKey(s, "config_file", "\"" + configFile + "\""));
        const Run r = tool == "detect" ? runTool(kDetect, {"--input", s}) : runTool(kEval, {"--session", s});
        QVERIFY2(r.refused(), qPrintable(r.describe()));
        QVERIFY(r.out.isEmpty());
        const QString last = r.errLines().value(r.errLines().size() - 1);
        QVERIFY2(contains(last.toUtf8(), {"config_file", configFile, "session"}), qPrintable(r.describe()));
    }

    // Defect 10: a frame file numbered past the limit is not counted by eval, and is named.
    void evalIgnoresFramesPastTheLimit()
    {
        const QString s = copyOfSession("past-limit");
        QVERIFY(QFile::copy(s + "/frames/000000.png", s + "/frames/1000000.png"));
        const Run r = runTool(kEval, {"--session", s, "--format", "csv"});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        QCOMPARE(parseCsv(r.out).at(0, "frames"), QString::number(kFrames));
        QVERIFY2(contains(r.err, {"1000000.png", "limit", "ignored"}), qPrintable(r.describe()));
        QVERIFY2(!r.err.contains("skipped"), qPrintable(r.describe()));
    }

    // Defect 11: truth.csv is there but no row is usable: say so, with the reason.
    void evalExplainsUnusableTruth()
    {
        const QString s = copyOfSession("bad-truth");
        QVERIFY(writeBytes(s + "/truth.csv", "frame,ball_visible,px,py,radius_px,x_m,y_m\n0,1,320,240,1e30,1,2\n"
                                             "1,1,abc,240,5,1,2\n"));
        const Run r = runTool(kEval, {"--session", s});
        QVERIFY2(r.refused(), qPrintable(r.describe()));
        QVERIFY(r.out.isEmpty());
        const QString last = r.errLines().value(r.errLines().size() - 1);
        QVERIFY2(!last.contains("has no truth.csv"), qPrintable(r.describe()));
        QVERIFY2(contains(last.toUtf8(), {s + "/truth.csv", "2 rows", "none is usable", "radius_px"}),
                 qPrintable(r.describe()));
    }

    // Defect 11: every frame failed (session.yml gives another frame size): nothing was
    // evaluated, which is a failure with the reason, not a table of zeros.
    void evalFailsWhenNothingWasEvaluated()
    {
        const QString s = copyOfSession("wrong-size");
        QVERIFY(setInfoKey(s, "frame_width", "320"));
        const Run r = runTool(kEval, {"--session", s});
        QVERIFY2(r.refused(), qPrintable(r.describe()));
        QVERIFY(r.out.isEmpty());
        const QString last = r.errLines().value(r.errLines().size() - 1);
        QVERIFY2(contains(last.toUtf8(), {s, "nothing evaluated", "320"}), qPrintable(r.describe()));
    }

    // Defect 3: a truth radius of 1e30 is refused with file and line; eval never prints inf.
    void evalRefusesImpossibleTruth()
    {
        const QString s = copyOfSession("huge-radius");
        QList<QByteArray> lines = readBytes(s + "/truth.csv").split('\n');
        QList<QByteArray> cells = lines[2].split(',');  // frame 1
        cells[4] = "1e30";
        cells[5] = "1e30";
        lines[2] = cells.join(',');
        QVERIFY(writeBytes(s + "/truth.csv", lines.join('\n')));
        const Run r = runTool(kEval, {"--session", s, "--format", "csv"});
        QVERIFY2(r.exitedWith(0), qPrintable(r.describe()));
        QVERIFY2(!r.out.contains("inf"), qPrintable(r.describe()));
        QCOMPARE(parseCsv(r.out).at(0, "annotated"), QString::number(kFrames - 1));
        QVERIFY2(contains(r.err, {s + "/truth.csv:3: radius_px: 1e+30"}), qPrintable(r.describe()));
    }
};

QTEST_GUILESS_MAIN(ToolsRobustnessTest)
#include "app_tools_robustness_test.moc"
