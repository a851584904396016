// Issue 14 and 13, the file primitives seen from the tools: a FIFO or deeply nested YAML where a
// file belongs is refused with its name (before: the tools hung or crashed), concurrent
// `omnitune-config --upgrade` runs of one file keep the original as .bak, the backup survives a
// second program run, and a save interrupted at every step (a test-only build of the writer
// with fault hooks, saving through the window's ConfigDocument when the GUI is built) leaves
// config, mask and backup each complete, old or new.
#include "calib/session/SessionWriter.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <opencv2/imgproc.hpp>

#include <QDir>
#include <QProcess>
#include <QtTest>

#include <sys/stat.h>

using namespace omnitune;

namespace {

const QString kConfig = QStringLiteral(OMNITUNE_CONFIG);
const QString kDetect = QStringLiteral(OMNITUNE_DETECT);
const QString kVictim = QStringLiteral(OMNITUNE_SAVE_VICTIM);
constexpr int kHangMs = 60 * 1000;  // far beyond any run here: not finishing means hung

// A tool run to its end (or killed as hung).
struct Ended {
    bool finished = false;  // exited by itself (also after a crash)
    bool crashed = false;
    int code = -1;
    QString err;

    QString text() const
    {
        return QString("%1, exit %2, stderr: %3").arg(finished ? (crashed ? "crashed" : "finished") : "hung").arg(code).arg(err.left(1500));
    }
};

Ended wait(QProcess& p)
{
    Ended e;
    e.finished = p.waitForFinished(kHangMs);
    if (!e.finished) {
        p.kill();
        p.waitForFinished();
    }
    e.crashed = p.exitStatus() == QProcess::CrashExit;
    e.code = p.exitCode();
    e.err = QString::fromUtf8(p.readAllStandardError());
    return e;
}

Ended run(const QString& program, const QStringList& args, const QStringList& env = {})
{
    QProcess p;
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    for (const QString& kv : env) e.insert(kv.section('=', 0, 0), kv.section('=', 1));
    p.setProcessEnvironment(e);
    p.start(program, args);
    return wait(p);
}

QByteArray bytes(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void put(const QString& path, const QByteArray& content)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(content);
}

void makeFifo(const QString& path)
{
    QFile::remove(path);
    QVERIFY2(::mkfifo(QFile::encodeName(path).constData(), 0644) == 0, qPrintable(path));
}

// A 3-frame session of the default config's size, with its config.yml (mask.png beside it).
void recordSession(const QString& folder)
{
    SessionInfo info;
    info.width = 640;
    info.height = 480;
    SessionCreate created = SessionWriter::create(folder.toStdString(), info);
    QVERIFY(created.writer);
    for (int i = 0; i < 3; ++i) {
        TruthRow truth;
        truth.ballVisible = false;
        QVERIFY(!created.writer->appendFrame(cv::Mat(480, 640, CV_8UC3, cv::Scalar(30, 120, 40)), truth));
    }
    Config config;
    config.geometry.maskFile = "mask.png";
    config.mask = cv::Mat(480, 640, CV_8UC1, cv::Scalar(255));
    QVERIFY(!created.writer->writeConfig(config));
    QVERIFY(!created.writer->finish());
}

// A config with a mask, as the window saves it; the original of every later test step.
void writeConfigWithMask(const QString& folder)
{
    Config c;
    c.geometry.maskFile = "mask.png";
    c.mask = cv::Mat(480, 640, CV_8UC1, cv::Scalar(255));
    cv::rectangle(c.mask, cv::Rect(300, 0, 40, 200), cv::Scalar(0), cv::FILLED);
    const auto err = saveConfig(c, (folder + "/config.yml").toStdString());
    QVERIFY2(!err, err ? err->toString().c_str() : "");
}

QStringList tempFiles(const QString& folder) { return QDir(folder).entryList({"*.tmp"}, QDir::Files); }

}  // namespace

class ConfigRobustnessTest : public QObject {
    Q_OBJECT
private slots:
    // Issue 14, defect 12: every file a tool opens may be a FIFO; it is named and refused or
    // skipped, and the tool ends (before: it waited for a writer for good).
    void fifoInsteadOfAFileIsRefused_data()
    {
        QTest::addColumn<QString>("fifo");  // in the session folder
        QTest::addColumn<bool>("check");    // omnitune-config --check, else omnitune-detect
        QTest::newRow("config.yml") << "config.yml" << true;
        QTest::newRow("mask") << "mask.png" << true;
        QTest::newRow("session.yml") << "session.yml" << false;
        QTest::newRow("truth.csv") << "truth.csv" << false;
        QTest::newRow("frame") << "frames/000001.png" << false;
    }
    void fifoInsteadOfAFileIsRefused()
    {
        QFETCH(QString, fifo);
        QFETCH(bool, check);
        QTemporaryDir dir;
        const QString session = dir.filePath("s");
        recordSession(session);
        QVERIFY(!saveConfig(Config{}, dir.filePath("config.yml").toStdString()));  // for detect: no mask
        makeFifo(session + "/" + fifo);
        const Ended e = check ? run(kConfig, {"--check", session + "/config.yml"})
                              : run(kDetect, {"--input", session, "--config", dir.filePath("config.yml")});
        QVERIFY2(e.finished && !e.crashed, qPrintable(e.text()));
        QVERIFY2(e.err.contains(QFileInfo(fifo).fileName()), qPrintable(e.text()));
        if (check) {
            QVERIFY2(e.code == 1, qPrintable(e.text()));
            QVERIFY2(e.err.contains("FIFO"), qPrintable(e.text()));
        }
    }

    // Issue 14, defect 1: 50,000 nested '[' (110 KB) overflowed the stack of OpenCV's parser.
    void deeplyNestedYamlIsRefused_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("config.yml") << "config.yml";
        QTest::newRow("session.yml") << "session.yml";
    }
    void deeplyNestedYamlIsRefused()
    {
        QFETCH(QString, file);
        QTemporaryDir dir;
        const QString session = dir.filePath("s");
        recordSession(session);
        QVERIFY(QFile::copy(session + "/mask.png", dir.filePath("mask.png")));
        QVERIFY(QFile::copy(session + "/config.yml", dir.filePath("config.yml")));
        const QByteArray head = file == "config.yml" ? "schema: 1\nx: " : "session_format: 1\nnotes: ";
        put(session + "/" + file, head + QByteArray(50000, '[') + QByteArray(60000, ' ') + "\n");
        const Ended e = file == "config.yml" ? run(kConfig, {"--check", session + "/config.yml"})
                                             : run(kDetect, {"--input", session, "--config", dir.filePath("config.yml")});
        QVERIFY2(e.finished && !e.crashed, qPrintable(e.text()));
        QVERIFY2(e.err.contains(file) && e.err.contains("nested more than 64 levels"), qPrintable(e.text()));
        if (file == "config.yml") QVERIFY2(e.code == 1, qPrintable(e.text()));
    }

    // Issue 14, defect 5: two `--upgrade` runs of one file at once. Before: one failed in about
    // half of the runs (a shared .tmp) and .bak became the new file.
    void concurrentUpgradesKeepTheOriginal()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        QByteArray original = QByteArray::fromStdString(serializeConfig(Config{}));
        original.replace("   gain: 200\n", "");  // an older config: --upgrade adds the key
        for (int round = 0; round < 25; ++round) {
            put(path, original);
            QFile::remove(path + ".bak");
            QProcess a, b;
            a.start(kConfig, {"--upgrade", path});
            b.start(kConfig, {"--upgrade", path});
            for (const Ended& e : {wait(a), wait(b)}) {
                QVERIFY2(e.finished && !e.crashed, qPrintable(e.text()));
                // Both succeed, or one says clearly that the other one is saving.
                QVERIFY2(e.code == 0 || (e.code == 1 && e.err.contains("another program")), qPrintable(e.text()));
            }
            QVERIFY2(bytes(path + ".bak") == original, qPrintable(QString("round %1").arg(round)));
            QVERIFY(loadConfig(path.toStdString()).ok());
            QCOMPARE(tempFiles(dir.path()), QStringList());
        }
    }

    // Issue 13, bug 6: after two program runs that save, .bak is still the file from before the
    // first. Before: every run refreshed it.
    void backupSurvivesASecondProgramRun()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        QByteArray original = QByteArray::fromStdString(serializeConfig(Config{}));
        original.replace("   gain: 200\n", "");
        put(path, original);
        const Ended first = run(kConfig, {"--upgrade", path});
        QVERIFY2(first.finished && first.code == 0, qPrintable(first.text()));
        QCOMPARE(bytes(path + ".bak"), original);
        QByteArray edited = bytes(path);
        edited.replace("   exposure: 300\n", "");  // the file changes between the runs
        put(path, edited);
        const Ended second = run(kConfig, {"--upgrade", path});
        QVERIFY2(second.finished && second.code == 0, qPrintable(second.text()));
        QCOMPARE(bytes(path + ".bak"), original);
    }

    // Issue 14, "Also": a save killed between any two of its steps (the temporaries written,
    // each backup kept, each rename) leaves config, mask and their backups each complete, old
    // or new, and the next save works.
    void interruptedSaveLeavesOldOrNew_data()
    {
        QTest::addColumn<QString>("stop");
        QTest::newRow("mask temp written") << "staged:1";
        QTest::newRow("both temps written") << "staged:2";
        QTest::newRow("before any rename") << "commit:1";
        QTest::newRow("mask backup kept") << "backup:1";
        QTest::newRow("mask renamed") << "commit:2";
        QTest::newRow("config backup kept") << "backup:2";
    }
    void interruptedSaveLeavesOldOrNew()
    {
        QFETCH(QString, stop);
        QTemporaryDir dir, fresh;
        writeConfigWithMask(dir.path());
        writeConfigWithMask(fresh.path());
        const QByteArray oldConfig = bytes(dir.filePath("config.yml")), oldMask = bytes(dir.filePath("mask.png"));
        const Ended clean = run(kVictim, {fresh.filePath("config.yml")});
        QVERIFY2(clean.finished && clean.code == 0, qPrintable(clean.text()));
        const QByteArray newConfig = bytes(fresh.filePath("config.yml")), newMask = bytes(fresh.filePath("mask.png"));
        QVERIFY(newConfig != oldConfig && newMask != oldMask);

        const Ended killed = run(kVictim, {dir.filePath("config.yml")}, {"OMNITUNE_FAULT_STOP=" + stop});
        QVERIFY2(killed.finished && killed.code == 86, qPrintable(killed.text()));  // stopped at that point
        const QByteArray config = bytes(dir.filePath("config.yml")), mask = bytes(dir.filePath("mask.png"));
        QVERIFY(config == oldConfig || config == newConfig);
        QVERIFY(mask == oldMask || mask == newMask);
        QVERIFY(!QFile::exists(dir.filePath("config.yml.bak")) || bytes(dir.filePath("config.yml.bak")) == oldConfig);
        QVERIFY(!QFile::exists(dir.filePath("mask.png.bak")) || bytes(dir.filePath("mask.png.bak")) == oldMask);
        QVERIFY(loadConfig(dir.filePath("config.yml").toStdString()).ok());

        const Ended again = run(kVictim, {dir.filePath("config.yml")});
        QVERIFY2(again.finished && again.code == 0, qPrintable(again.text()));
        QCOMPARE(bytes(dir.filePath("config.yml.bak")), oldConfig);
        QCOMPARE(bytes(dir.filePath("mask.png.bak")), oldMask);
    }

    // Issue 14, defect 4, where hard links are not available (a FAT stick): the backup is then
    // a copy written to a temporary and renamed, so a failing write leaves no partial .bak.
    void backupCopyIsNeverPartial()
    {
        QTemporaryDir dir;
        writeConfigWithMask(dir.path());
        const QByteArray oldConfig = bytes(dir.filePath("config.yml")), oldMask = bytes(dir.filePath("mask.png"));
        // The third write is the copy of the old mask: it fails as on a full disk.
        const Ended failed = run(kVictim, {dir.filePath("config.yml")}, {"OMNITUNE_FAULT_FAIL=link,write:3"});
        QVERIFY2(failed.finished && failed.code == 1, qPrintable(failed.text()));
        QVERIFY2(failed.err.contains("mask.png.bak") && failed.err.contains("No space left"), qPrintable(failed.text()));
        QCOMPARE(bytes(dir.filePath("config.yml")), oldConfig);
        QCOMPARE(bytes(dir.filePath("mask.png")), oldMask);
        QVERIFY(!QFile::exists(dir.filePath("mask.png.bak")));
        QVERIFY(!QFile::exists(dir.filePath("config.yml.bak")));
        QCOMPARE(tempFiles(dir.path()), QStringList());

        const Ended copied = run(kVictim, {dir.filePath("config.yml")}, {"OMNITUNE_FAULT_FAIL=link"});
        QVERIFY2(copied.finished && copied.code == 0, qPrintable(copied.text()));
        QCOMPARE(bytes(dir.filePath("config.yml.bak")), oldConfig);
        QCOMPARE(bytes(dir.filePath("mask.png.bak")), oldMask);
    }
};

QTEST_GUILESS_MAIN(ConfigRobustnessTest)
#include "app_config_robustness_test.moc"
