// Crash recovery of unsaved config edits (widgets/RecoveryFile, RecoveryOffer), offscreen on a
// copy of the demo session: a window killed with SIGKILL after an edit leaves a recovery file,
// and the next window that opens the session offers it, listing "key: saved → recovered";
// Restore applies it as one undo step and leaves the document unsaved. Saving removes the file,
// Discard removes it, Not now keeps it, an unreadable one is reported and kept, and a second
// window on the same config leaves the first one's live file alone.
#include "app/MainWindow.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"
#include "widgets/NoticeBar.h"
#include "widgets/RecoveryFile.h"
#include "WindowTestSupport.h"

#include <QProcess>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

// Answers every message box that opens while it lives with `button`, keeping what each said.
class BoxAnswerer {
public:
    explicit BoxAnswerer(QMessageBox::StandardButton button)
    {
        timer_.setInterval(10);
        QObject::connect(&timer_, &QTimer::timeout, [this, button] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) return;
            texts << box->text();
            details << box->informativeText();
            box->button(button)->click();
        });
        timer_.start();
    }
    QStringList texts;
    QStringList details;

private:
    QTimer timer_;
};

}  // namespace

class CrashRecoveryTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    QString session_;
    QString config_;
    int sessionCount_ = 0;

    int savedCannyLow() const { return loadConfig(config_.toStdString()).config.edges.cannyLow; }

    // A recovery file for the session's config as a crashed run would have left it.
    void leaveRecoveryFile(const Config& edited)
    {
        QDir().mkpath(RecoveryFile::directory());
        QVERIFY(!writeFileAtomically(RecoveryFile::fileFor(config_).toStdString(), serializeConfig(edited), false));
    }

private slots:
    void initTestCase()
    {
        QVERIFY(tmp_.isValid());
        QStandardPaths::setTestModeEnabled(true);
        qputenv("OMNITUNE_RECOVERY_DIR", tmp_.filePath("recovery").toUtf8());
    }

    void init()
    {
        session_ = tmp_.filePath(QStringLiteral("demo-%1").arg(++sessionCount_));
        QVERIFY(copyDemo(session_));
        config_ = session_ + "/config.yml";
    }

    void killedWindowsEditIsOfferedAndRestored()
    {
        const int saved = savedCannyLow();
        const int edited = saved + 17;
        const QString recoveryFile = RecoveryFile::fileFor(config_);
        QVERIFY(!QFile::exists(recoveryFile));

        QProcess child;
        child.setProcessChannelMode(QProcess::ForwardedChannels);
        child.start(QStringLiteral(OMNITUNE_RECOVERY_CHILD), {session_, "edges.canny_low", QString::number(edited)});
        QVERIFY(child.waitForStarted());
        // The edit is kept a few seconds after it was made (RecoveryFile::kDebounceMs).
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(recoveryFile) || child.state() == QProcess::NotRunning, 60000);
        QCOMPARE(child.state(), QProcess::Running);
        child.kill();  // SIGKILL: no close event, no save, no clean-up
        QVERIFY(child.waitForFinished());
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);
        QVERIFY(QFile::exists(recoveryFile));
        QCOMPARE(savedCannyLow(), saved);  // the config file never saw the edit

        MainWindow window;
        window.show();
        BoxAnswerer restore(QMessageBox::Yes);  // "Restore"
        QVERIFY(window.openSource(session_));
        QCOMPARE(restore.texts.size(), 1);
        QVERIFY2(restore.texts.front().contains("1 edit(s) of config.yml"), qPrintable(restore.texts.front()));
        QCOMPARE(std::get<int>(window.document()->value("edges.canny_low")), edited);
        QVERIFY(window.document()->isDirty());
        QVERIFY(window.isWindowModified());
        QVERIFY(window.notices()->text().contains("Restored 1 recovered edit(s)"));

        // One Ctrl+Z takes the whole restore back.
        window.activateWindow();  // the offer had it
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(std::get<int>(window.document()->value("edges.canny_low")), saved);
        QVERIFY(!window.document()->isDirty());
        QVERIFY(!QFile::exists(recoveryFile));  // back to the saved state: nothing to recover
    }

    void offerListsSavedAndRecoveredValues()
    {
        Config edited = loadConfig(config_.toStdString()).config;
        // Both above the saved canny_high: restoring canny_low first alone would be refused.
        edited.edges.cannyLow = 300;
        edited.edges.cannyHigh = 400;
        leaveRecoveryFile(edited);

        MainWindow window;
        BoxAnswerer restore(QMessageBox::Yes);
        QVERIFY(window.openSource(session_));
        QCOMPARE(restore.details.size(), 1);
        const QString details = restore.details.front();
        QVERIFY2(details.contains(QString::fromUtf8("edges.canny_low: 60 \u2192 300")), qPrintable(details));
        QVERIFY2(details.contains(QString::fromUtf8("edges.canny_high: 180 \u2192 400")), qPrintable(details));
        QCOMPARE(std::get<int>(window.document()->value("edges.canny_low")), 300);
        QCOMPARE(std::get<int>(window.document()->value("edges.canny_high")), 400);
        QCOMPARE(window.document()->undoStack()->count(), 1);  // one step, whatever the order

        // Saving keeps the edits in the config and removes the recovery file.
        QVERIFY(window.saveConfig());
        QCOMPARE(savedCannyLow(), 300);
        QVERIFY(!QFile::exists(RecoveryFile::fileFor(config_)));
    }

    // Class edits (the colour class editor's replaceConfig steps) are no schema keys: they must be
    // recovered too, as one step.
    void colourClassEditsAreRestored()
    {
        Config edited = loadConfig(config_.toStdString()).config;
        edited.colors.classes[std::size_t(ColorClass::Yellow) - 1].enabled = true;
        edited.colors.classes[std::size_t(ColorClass::Green) - 1].boxes.push_back(HsvRange{true, 86, 98, 50, 255, 30, 255});
        leaveRecoveryFile(edited);

        MainWindow window;
        BoxAnswerer restore(QMessageBox::Yes);
        QVERIFY(window.openSource(session_));
        QCOMPARE(restore.details.size(), 1);
        QVERIFY2(restore.details.front().contains("colors.classes"), qPrintable(restore.details.front()));
        QVERIFY(window.document()->config().colors.classes == edited.colors.classes);
        QVERIFY(window.document()->isDirty());
        QCOMPARE(window.document()->undoStack()->count(), 1);
        QVERIFY(window.saveConfig());
        QVERIFY(loadConfig(config_.toStdString()).config.colors.classes == edited.colors.classes);
    }

    void editsAreWrittenAndRemovedOnSave()
    {
        MainWindow window;
        QVERIFY(window.openSource(session_));
        window.recovery()->setIntervals(10, 1000);
        const QString file = RecoveryFile::fileFor(config_);
        QVERIFY(!window.document()->setValue("edges.canny_high", 222));
        QTRY_VERIFY(QFile::exists(file));
        QFile in(file);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const ConfigLoad kept = parseConfig(in.readAll().toStdString(), "recovery.yml");
        QVERIFY(kept.ok());
        QCOMPARE(kept.config.edges.cannyHigh, 222);
        QVERIFY(window.saveConfig());
        QVERIFY(!QFile::exists(file));
    }

    // Two windows on one config: the second must not take the first one's live edits for a
    // crash's (the recovery file's lock names a running process).
    void liveEditsOfAnotherWindowAreNotOffered()
    {
        MainWindow first;
        QVERIFY(first.openSource(session_));
        QVERIFY(!first.document()->setValue("edges.canny_high", 203));
        QVERIFY(!first.recovery()->writeNow());
        const QString file = RecoveryFile::fileFor(config_);
        QVERIFY(QFile::exists(file));

        MainWindow second;
        BoxAnswerer none(QMessageBox::Discard);
        QVERIFY(second.openSource(session_));
        QVERIFY(none.texts.isEmpty());
        QVERIFY(QFile::exists(file));
        QVERIFY(!second.document()->setValue("edges.canny_high", 204));
        QVERIFY(second.recovery()->writeNow());  // refused: the file is the first window's
        QVERIFY(second.notices()->text().contains("another OmniTune window"));
        second.document()->undoStack()->setClean();
        first.document()->undoStack()->setClean();
        QVERIFY(!QFile::exists(file));
    }

    // A slider dragged for minutes restarts the short delay on every step; the file is still
    // written once the first unwritten edit is RecoveryFile::kMaxAgeMs old.
    void keptWhileEditsKeepComing()
    {
        MainWindow window;
        QVERIFY(window.openSource(session_));
        window.recovery()->setIntervals(3600 * 1000, 20);
        QVERIFY(!window.document()->setValue("edges.canny_high", 201));
        QTRY_VERIFY(QFile::exists(RecoveryFile::fileFor(config_)));
        window.document()->undoStack()->setClean();
    }

    // The recovery folder cannot be written: the window says so and keeps the edits in memory.
    void writeFailureIsReported()
    {
        const QByteArray dir = qgetenv("OMNITUNE_RECOVERY_DIR");
        const QString blocker = tmp_.filePath("not-a-folder");
        QFile f(blocker);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.close();
        qputenv("OMNITUNE_RECOVERY_DIR", blocker.toUtf8());
        MainWindow window;
        QVERIFY(window.openSource(session_));
        QVERIFY(!window.document()->setValue("edges.canny_high", 202));
        QSignalSpy failures(window.recovery(), &RecoveryFile::writeFailed);
        const auto error = window.recovery()->writeNow();
        QVERIFY(!window.document()->setValue("edges.canny_high", 203));
        QVERIFY(window.recovery()->writeNow());
        qputenv("OMNITUNE_RECOVERY_DIR", dir);
        QVERIFY(error);
        QVERIFY2(window.notices()->text().contains("cannot be kept for crash recovery"), qPrintable(window.notices()->text()));
        QCOMPARE(failures.count(), 1);  // said once, not after every edit
        QCOMPARE(std::get<int>(window.document()->value("edges.canny_high")), 203);
        window.document()->undoStack()->setClean();
    }

    void discardRemovesTheFileAndNotNowKeepsIt()
    {
        Config edited = loadConfig(config_.toStdString()).config;
        edited.edges.cannyHigh = 250;
        leaveRecoveryFile(edited);
        const QString file = RecoveryFile::fileFor(config_);
        {
            MainWindow window;
            BoxAnswerer notNow(QMessageBox::Cancel);
            QVERIFY(window.openSource(session_));
            QCOMPARE(notNow.texts.size(), 1);
            QCOMPARE(std::get<int>(window.document()->value("edges.canny_high")), 180);
            QVERIFY(!window.document()->isDirty());
            QVERIFY(QFile::exists(file));
        }
        MainWindow window;
        BoxAnswerer discard(QMessageBox::Discard);
        QVERIFY(window.openSource(session_));
        QCOMPARE(discard.texts.size(), 1);
        QCOMPARE(std::get<int>(window.document()->value("edges.canny_high")), 180);
        QVERIFY(!window.document()->isDirty());
        QVERIFY(!QFile::exists(file));
    }

    // Edits of the defaults (a source without config.yml) are kept as "untitled" and offered
    // when the next source without a config opens.
    void editsOfAConfigWithoutFileAreKeptToo()
    {
        const QString frames = session_ + "/frames";  // an image folder: no config of its own
        const QString file = RecoveryFile::fileFor(QString());
        {
            MainWindow window;
            QVERIFY(window.openSource(frames));
            QVERIFY(window.document()->path().isEmpty());
            QVERIFY(!window.document()->setValue("edges.canny_high", 190));
            QVERIFY(!window.recovery()->writeNow());
            QCOMPARE(window.recovery()->writtenFile(), file);
            QVERIFY(QFile::exists(file));
        }  // destroyed without closing, as in a crash: the file stays
        QVERIFY(QFile::exists(file));
        MainWindow window;
        BoxAnswerer restore(QMessageBox::Yes);
        QVERIFY(window.openSource(frames));
        QCOMPARE(restore.texts.size(), 1);
        QVERIFY(restore.texts.front().contains("the default config"));
        QCOMPARE(std::get<int>(window.document()->value("edges.canny_high")), 190);
        QVERIFY(window.document()->isDirty());
        window.document()->undoStack()->setClean();
        QVERIFY(!QFile::exists(file));
    }

    void unreadableRecoveryFileIsReportedAndKept()
    {
        const QString file = RecoveryFile::fileFor(config_);
        QDir().mkpath(RecoveryFile::directory());
        QFile out(file);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write("schema: 1\nedges: [\n");
        out.close();
        MainWindow window;
        BoxAnswerer none(QMessageBox::Yes);
        QVERIFY(window.openSource(session_));
        QVERIFY(none.texts.isEmpty());  // nothing to offer: a notice, no question
        QVERIFY(!window.document()->isDirty());
        QVERIFY2(window.notices()->text().contains("cannot be read"), qPrintable(window.notices()->text()));
        QVERIFY(window.notices()->text().contains(file));
        QVERIFY(QFile::exists(file));
    }
};

QTEST_MAIN(CrashRecoveryTest)
#include "app_crash_recovery_test.moc"
