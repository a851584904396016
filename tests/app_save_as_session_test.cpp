// File > Save as session... (issue 11), offscreen, driving the real window: an image folder
// (the demo's frames without session.yml) is saved as a session through the action, the
// window reopens it as a session, a ball is marked, and Apply to whole session then gives a
// detection ratio. Asking to mark truth on the image folder offers the same, and Yes ends
// in marking mode on the new session.
#include "app/MainWindow.h"
#include "calib/session/SessionReader.h"
#include "widgets/SaveAsSession.h"
#include "widgets/SessionSweepPanel.h"
#include "widgets/TruthMarker.h"
#include "WindowTestSupport.h"

#include <QAction>
#include <QStatusBar>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

class SaveAsSessionTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    int folders_ = 0;

    // The demo's frames as a plain image folder, and the demo's config beside it.
    QString imageFolder()
    {
        const QString demo = tmp_.filePath(QStringLiteral("demo-%1").arg(folders_++));
        if (!copyDemo(demo)) return {};
        const QString images = demo + "-images";
        QDir().mkpath(images);
        for (const QString& f : QDir(demo + "/frames").entryList({"*.png"}, QDir::Files))
            if (!QFile::copy(demo + "/frames/" + f, images + "/" + f)) return {};
        return images;
    }

    void openImagesWithDemoConfig(MainWindow& window, const QString& images)
    {
        QVERIFY(window.openConfig(images.left(images.size() - QStringLiteral("-images").size()) + "/config.yml"));
        QVERIFY(window.openSource(images));
        QVERIFY(waitForFrame(window, 0));
        QVERIFY(!window.truth()->isOpen());  // an image folder has no truth.csv
    }

private slots:
    void initTestCase()
    {
        startWindowTests();
    }

    void imageFolderSavedMarkedAndSwept()
    {
        const QString images = imageFolder();
        QVERIFY(!images.isEmpty());
        MainWindow window;
        QVERIFY(showActive(window));
        auto* action = window.findChild<QAction*>("saveAsSession");
        QVERIFY(action);
        QVERIFY(!action->isEnabled());  // nothing to save yet
        openImagesWithDemoConfig(window, images);
        QVERIFY(action->isEnabled());

        const QString target = tmp_.filePath("saved-session");
        QString suggested;
        window.findChild<SaveAsSession*>()->setFolderAsker([&](const QString& s) {
            suggested = s;
            return target;
        });
        action->trigger();
        QCOMPARE(suggested, images + "-session");
        QVERIFY(waitForFrame(window, 0));

        // The window now shows the session, with its truth open and its config.
        QVERIFY(window.truth()->isOpen());
        QVERIFY2(window.windowTitle().contains("saved-session"), qPrintable(window.windowTitle()));
        QCOMPARE(QFileInfo(window.document()->path()).absoluteFilePath(), QFileInfo(target + "/config.yml").absoluteFilePath());
        SessionOpen saved = SessionReader::open(target.toStdString());
        QVERIFY(saved.ok());
        QCOMPARE(saved.reader->frameCount(), 24);
        QVERIFY(saved.reader->hasTruthFile());

        // Mark frame 0 with the detector's ball (T, then A) and sweep.
        QVERIFY(window.lastRun()->result.detection.found);
        QTest::keyClick(&window, Qt::Key_T);
        QVERIFY2(window.truthMarker()->isMarking(), qPrintable(window.statusBar()->currentMessage() + " active: " + (QApplication::activeWindow() ? QApplication::activeWindow()->objectName() + QApplication::activeWindow()->metaObject()->className() : QString("none"))));
        QTest::keyClick(&window, Qt::Key_A);
        QVERIFY(window.truth()->row(0) && window.truth()->row(0)->ballVisible);
        QCOMPARE(int(SessionReader::open(target.toStdString()).reader->truth().size()), 1);  // on disk

        window.findChild<QAction*>("applyToSession")->trigger();
        auto* panel = window.findChild<SessionSweepPanel*>();
        QVERIFY(panel);
        QSignalSpy finished(panel, &SessionSweepPanel::sweepFinished);
        QVERIFY(finished.wait(60000));
        const auto result = finished.at(0).at(0).value<std::shared_ptr<const SweepResult>>();
        QVERIFY2(result->ok(), result->error.c_str());
        QVERIFY(result->hasTruth);
        QCOMPARE(result->currentRow.withBall, 1);
        QCOMPARE(result->currentRow.detectionRatioPct, 100.0);
        QVERIFY2(panel->summaryText().contains("Detection ratio"), qPrintable(panel->summaryText()));
    }

    void markingOnImagesOffersASession()
    {
        const QString images = imageFolder();
        MainWindow window;
        QVERIFY(showActive(window));
        openImagesWithDemoConfig(window, images);
        const QString target = tmp_.filePath("offered-session");
        window.findChild<SaveAsSession*>()->setFolderAsker([&](const QString&) { return target; });

        // No: nothing is written, marking stays off.
        QString question;
        answerNextMessageBox(QMessageBox::No, &question);
        QTest::keyClick(&window, Qt::Key_T);
        QTRY_VERIFY(!question.isEmpty());
        QVERIFY2(question.contains("not a session"), qPrintable(question));
        QVERIFY(!QFileInfo::exists(target));
        QVERIFY(!window.truthMarker()->isMarking());

        // Yes: saved, opened, and marking on.
        window.activateWindow();  // offscreen, a closed message box leaves no window active
        QVERIFY(QTest::qWaitForWindowActive(&window));
        question.clear();
        answerNextMessageBox(QMessageBox::Yes, &question);
        QTest::keyClick(&window, Qt::Key_T);
        QTRY_VERIFY2(window.truthMarker()->isMarking(), qPrintable(question + " | " + window.statusBar()->currentMessage()));
        QVERIFY(window.truth()->isOpen());
        QVERIFY(QFileInfo::exists(target + "/session.yml"));
        QVERIFY(waitForFrame(window, 0));
    }
};

QTEST_MAIN(SaveAsSessionTest)
#include "app_save_as_session_test.moc"
