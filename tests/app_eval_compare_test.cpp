// omnitune-eval --compare A.yml B.yml, run as a user runs it (QProcess on the built binary) on
// the demo session: the Markdown table has one row per config and the changed frames; the same
// config twice reports no change; bad use (one file, a missing file, two sessions) exits
// non-zero with one line on stderr naming the fault.
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kEval = QStringLiteral(OMNITUNE_EVAL);
const QString kDemo = QStringLiteral(OMNITUNE_SOURCE_DIR "/sessions/demo");

struct Run {
    int exitCode = -1;
    bool crashed = true;
    QString out, err;
};

Run eval(const QStringList& args)
{
    QProcess p;
    p.start(kEval, args);
    Run r;
    if (!p.waitForFinished(10 * 60 * 1000)) return r;
    r.crashed = p.exitStatus() != QProcess::NormalExit;
    r.exitCode = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

}  // namespace

using namespace omnitune;

class EvalCompareTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    QString strict_;

private slots:
    void initTestCase()
    {
        QVERIFY(tmp_.isValid());
        ConfigLoad load = loadConfig((kDemo + "/config.yml").toStdString());
        QVERIFY(load.ok());
        load.config.validation.minCircularityPct = 100.0;  // loses most balls of the demo
        load.config.validation.circleFit = false;  // (in the thesis' band; a fitted circle takes them all)
        strict_ = tmp_.filePath("strict.yml");
        QVERIFY(!saveConfig(load.config, strict_.toStdString(), false));
    }

    void comparesTwoConfigs()
    {
        const Run r = eval({"--session", kDemo, "--compare", strict_, kDemo + "/config.yml"});
        QVERIFY2(!r.crashed && r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.startsWith("| config | frames |"), qPrintable(r.out));
        QVERIFY2(r.out.contains(QRegularExpression(R"(\n\| strict\.yml \| 24 \| 0 \| \d+ )")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QRegularExpression(R"(\n\| config\.yml \| 24 \| 0 \| \d+ )")), qPrintable(r.out));
        const QRegularExpressionMatch m =
            QRegularExpression(R"(Changed frames: (\d+) of 24 \(0 appeared, (\d+) vanished, 0 moved)").match(r.out);
        QVERIFY2(m.hasMatch(), qPrintable(r.out));
        QVERIFY(m.captured(2).toInt() > 0);
        QVERIFY2(r.out.contains(QRegularExpression(R"(- vanished \(only config\.yml finds a ball\): \d+( \d+)*\n)")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains("- appeared (only strict.yml finds a ball): none"), qPrintable(r.out));
    }

    void sameConfigTwiceChangesNothing()
    {
        const QString config = kDemo + "/config.yml";
        const Run r = eval({"--session", kDemo, "--compare", config, "--compare", config});
        QVERIFY2(!r.crashed && r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("| A: " + config + " | 24 |") && r.out.contains("| B: " + config + " | 24 |"),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains("no frame changed"), qPrintable(r.out));
    }

    void withoutTruthOnlyDetections()
    {
        // A copy of the demo without truth.csv: detections and changes, no ratio to claim.
        const QString session = tmp_.filePath("notruth");
        QVERIFY(QDir().mkpath(session + "/frames"));
        for (const char* f : {"session.yml", "config.yml"}) QVERIFY(QFile::copy(kDemo + "/" + QLatin1String(f), session + "/" + QLatin1String(f)));
        for (const QString& f : QDir(kDemo + "/frames").entryList(QDir::Files))
            QVERIFY(QFile::copy(kDemo + "/frames/" + f, session + "/frames/" + f));
        const Run r = eval({"--session", session, "--compare", strict_, session + "/config.yml"});
        QVERIFY2(!r.crashed && r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QRegularExpression(R"(\n\| strict\.yml \| 24 \| 0 \| \d+ \(\d+\.\d %\) \| n/a \| n/a \|)")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains("No truth.csv"), qPrintable(r.out));
        QVERIFY2(r.out.contains(QRegularExpression(R"(Changed frames: \d+ of 24)")), qPrintable(r.out));
    }

    void badUseIsRefused_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString config = kDemo + "/config.yml";
        QTest::newRow("one file") << QStringList{"--session", kDemo, "--compare", config} << "needs two config files";
        QTest::newRow("missing file") << QStringList{"--session", kDemo, "--compare", config, kDemo + "/nope.yml"}
                                      << "nope.yml";
        QTest::newRow("two sessions") << QStringList{"--session", kDemo, "--session", kDemo, "--compare", config, config}
                                      << "one --session";
        QTest::newRow("with --config") << QStringList{"--session", kDemo, "--config", config, "--compare", config, config}
                                       << "drop --config";
    }

    void badUseIsRefused()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = eval(args);
        QVERIFY(!r.crashed);
        QVERIFY2(r.exitCode != 0, qPrintable(r.out));
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.startsWith("omnitune-eval: ") && r.err.contains(message), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(EvalCompareTest)
#include "app_eval_compare_test.moc"
