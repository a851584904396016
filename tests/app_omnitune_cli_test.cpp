// The workbench's command line: --help and --version print and exit 0 (before any window,
// so they work without a display), and an unknown option is one line on stderr and a
// non-zero exit rather than a file the window tries to open.
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

class OmniTuneCliTest : public QObject {
    Q_OBJECT
private:
    struct Result {
        int exitCode = -1;
        QString out;
        QString err;
    };
    static Result run(const QStringList& args)
    {
        QProcess p;
        p.start(QStringLiteral(OMNITUNE_BINARY), args);
        Result r;
        if (!p.waitForFinished(30000)) return r;
        r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        r.out = QString::fromLocal8Bit(p.readAllStandardOutput());
        r.err = QString::fromLocal8Bit(p.readAllStandardError());
        return r;
    }

private slots:
    void helpPrintsAndExits()
    {
        const Result r = run({QStringLiteral("--help")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("Usage:") && r.out.contains("--version") && r.out.contains("source"), qPrintable(r.out));
    }
    void versionIsTheProjects()
    {
        const Result r = run({QStringLiteral("--version")});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.trimmed(), QStringLiteral("OmniTune " OMNITUNE_PROJECT_VERSION));
    }
    void unknownOptionIsOneLineAndFails()
    {
        const Result r = run({QStringLiteral("--bogus")});
        QVERIFY(r.exitCode != 0);
        // One line of ours (Qt may add its own about the environment, e.g. XDG_RUNTIME_DIR).
        const QStringList ours = r.err.split('\n').filter(QRegularExpression("^omnitune: "));
        QVERIFY2(ours.size() == 1 && ours.front().contains("bogus"), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
};

QTEST_GUILESS_MAIN(OmniTuneCliTest)
#include "app_omnitune_cli_test.moc"
