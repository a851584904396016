// A newcomer's path (issue 11): the camera's frames as an image folder, a config edit, then
// File > Save as session. The new session holds the edit in its config.yml, so opening it asks
// nothing about unsaved changes (it used to ask to save edits the session already held), and
// the window shows it clean with the edit.
#include "app/MainWindow.h"
#include "core/ConfigParser.h"
#include "widgets/ConfigDocument.h"
#include "widgets/SaveAsSession.h"
#include "WindowTestSupport.h"

#include <QAction>
#include <QMessageBox>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

class SetupNewSessionTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;

private slots:
    void initTestCase()
    {
        startWindowTests();
    }

    void savedSessionOpensWithTheEditsUnasked()
    {
        const QString demo = tmp_.filePath("demo");
        QVERIFY(copyDemo(demo));
        const QString images = tmp_.filePath("images");
        QDir().mkpath(images);
        for (const QString& f : QDir(demo + "/frames").entryList({"*.png"}, QDir::Files))
            QVERIFY(QFile::copy(demo + "/frames/" + f, images + "/" + f));
        MainWindow window;
        QVERIFY(openSetupWindow(window, images, demo + "/config.yml"));
        ConfigDocument* doc = window.document();
        const double edited = doc->config().geometry.innerRadius + 3;
        QVERIFY(!doc->setValue("geometry.inner_radius", edited));
        QVERIFY(doc->isDirty());

        const QString target = tmp_.filePath("session");
        window.findChild<SaveAsSession*>()->setFolderAsker([&](const QString&) { return target; });
        // Any message box now is the old question: answer Cancel, which would keep the images open.
        QString asked;
        answerNextMessageBox(QMessageBox::Cancel, &asked);
        window.findChild<QAction*>("saveAsSession")->trigger();
        QVERIFY(waitForFrame(window, 0));
        QVERIFY2(QFileInfo(doc->path()).absoluteFilePath() == QFileInfo(target + "/config.yml").absoluteFilePath(),
                 qPrintable(doc->path() + " / asked: " + asked));
        QVERIFY(!doc->isDirty());
        QCOMPARE(doc->config().geometry.innerRadius, edited);
        const ConfigLoad saved = loadConfig((target + "/config.yml").toStdString());
        QVERIFY(saved.ok());
        QCOMPARE(saved.config.geometry.innerRadius, edited);
        // The demo's own config file keeps what it had (the edit went with the new session).
        const ConfigLoad original = loadConfig((demo + "/config.yml").toStdString());
        QVERIFY(original.ok());
        QVERIFY(original.config.geometry.innerRadius != edited);
        QVERIFY2(asked.isEmpty(), qPrintable(asked));
    }
};

QTEST_MAIN(SetupNewSessionTest)
#include "app_setup_new_session_test.moc"
