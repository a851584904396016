// Venue profiles in the window's Colours tab (issue 10), offscreen on a copy of the demo session:
// Save as writes colour-profiles/NAME.yml beside the config and lists it; Load replaces the
// classes in one undo step (undo restores them); Compare opens the diff view with the changed
// class highlighted and the frame's changed pixels counted; a corrupt profile file is listed as
// not loading and Load names the file and the fault; Delete removes the file. And the same on
// the command line: omnitune-calibrate colours --profile-save / --profile-list / --profile-load.
#include "app/MainWindow.h"
#include "calib/colour/ColourProfile.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"
#include "widgets/ColourDiffView.h"
#include "widgets/ColourEditor.h"
#include "widgets/ColourProfilesBox.h"
#include "widgets/ConfigDocument.h"
#include "FileBytes.h"
#include "ToolRun.h"
#include "WindowTestSupport.h"

#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QListWidget>
#include <QStatusBar>
#include <QTableWidget>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;
using filetest::writeFile;

class ColourProfilesTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    std::unique_ptr<MainWindow> window_;

    ColourProfilesBox* box() const { return window_->colourEditor()->profiles(); }
    ConfigDocument* doc() const { return window_->document(); }

    QString openDemo()
    {
        const QString session = freshDemo(tmp_);
        if (session.isEmpty() || !openWindow(window_, session, Shown::AsIs, [](MainWindow& w) { w.findChild<QDockWidget*>("colours")->raise(); })) return {};
        return session;
    }

    int rowOf(const QString& text) const
    {
        for (int i = 0; i < box()->list()->count(); ++i)
            if (box()->list()->item(i)->text() == text) return i;
        return -1;
    }

private slots:
    void initTestCase()
    {
        startWindowTests();
    }
    void cleanup() { window_.reset(); }

    void saveLoadCompareDeleteInTheWindow()
    {
        QVERIFY(!openDemo().isEmpty());
        QVERIFY(!doc()->path().isEmpty());
        const Config original = doc()->config();

        // Save the config's colours as "Home lab".
        QVERIFY(!box()->saveProfile(QStringLiteral("Home lab")));
        const QString homeFile = box()->folder() + "/home-lab.yml";
        QVERIFY(QFileInfo::exists(homeFile));
        QVERIFY(rowOf(QStringLiteral("Home lab")) >= 0);

        // A second calibration: green's hue box narrowed, saved as "Venue field A".
        Config venue = original;
        const int green = findColourClass(venue.colors.classes, "green");
        QVERIFY(green >= 0);
        venue.colors.classes[std::size_t(green)].boxes[0].hMax -= 15;
        QVERIFY(!doc()->replaceConfig(venue, QStringLiteral("narrow green")));
        QVERIFY(!box()->saveProfile(QStringLiteral("Venue field A")));
        QCOMPARE(box()->list()->count(), 2);

        // Back to the home lab's colours: Load is one undo step, undo restores the venue's.
        box()->list()->setCurrentRow(rowOf(QStringLiteral("Home lab")));
        const int steps = doc()->undoStack()->count();
        QTest::mouseClick(box()->findChild<QPushButton*>("loadProfile"), Qt::LeftButton);
        QCOMPARE(doc()->config().colors.classes, original.colors.classes);
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        doc()->undoStack()->undo();
        QCOMPARE(doc()->config().colors.classes, venue.colors.classes);
        doc()->undoStack()->redo();

        // Compare the venue's profile with the config (the home lab's colours): green differs.
        box()->list()->setCurrentRow(rowOf(QStringLiteral("Venue field A")));
        QTest::mouseClick(box()->findChild<QPushButton*>("compareProfile"), Qt::LeftButton);
        ColourDiffView* diff = box()->diffView();
        QVERIFY(diff && diff->isVisible());
        QTableWidget* table = diff->table();
        int greenRow = -1;
        for (int r = 0; r < table->rowCount(); ++r)
            if (table->item(r, 0)->text() == QStringLiteral("class green")) greenRow = r;
        QVERIFY(greenRow >= 0);
        QVERIFY(table->item(greenRow, 1)->text() != table->item(greenRow, 2)->text());
        QVERIFY(table->item(greenRow, 0)->background().style() != Qt::NoBrush);  // highlighted
        QCOMPARE(table->item(0, 0)->background().style(), Qt::NoBrush);          // lut_bits: the same
        QVERIFY(diff->changedPixels() > 0);  // the demo frame's carpet at the cut-off hues
        QVERIFY(!diff->picture()->pixmap(Qt::ReturnByValue).isNull());
        QVERIFY(diff->summary()->text().contains(QStringLiteral("%")));
        diff->close();

        // A corrupt profile: listed as not loading; Load names the file and the fault.
        const QString bad = box()->folder() + "/broken.yml";
        writeFile(bad.toStdString(), "%YAML:1.0\n---\ncolour_profile: 1\nname: \"broken\"\ncolors:\n   lut_bits: 12\n");
        box()->refreshList();
        const int badRow = rowOf(QStringLiteral("broken.yml (does not load)"));
        QVERIFY(badRow >= 0);
        box()->list()->setCurrentRow(badRow);
        const Config before = doc()->config();
        QSignalSpy said(box(), &ColourProfilesBox::message);
        QTest::mouseClick(box()->findChild<QPushButton*>("loadProfile"), Qt::LeftButton);
        QCOMPARE(said.count(), 1);
        const QString why = said.takeFirst().at(0).toString();
        QVERIFY2(why.contains(QStringLiteral("broken.yml")) && why.contains(QStringLiteral("lut_bits")), qPrintable(why));
        QCOMPARE(doc()->config().colors.classes, before.colors.classes);  // nothing loaded

        // Delete removes the file and the row.
        QVERIFY(!box()->deleteProfile(homeFile));
        QVERIFY(!QFileInfo::exists(homeFile));
        QCOMPARE(rowOf(QStringLiteral("Home lab")), -1);
    }

    // With OMNITUNE_SCREENSHOT_DIR set: the profiles group and the diff view for the user guide
    // (docs/images/colour-profiles.png, colour-diff.png; under xvfb-run for real fonts).
    void screenshot()
    {
        const QString dir = qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR");
        if (dir.isEmpty()) QSKIP("OMNITUNE_SCREENSHOT_DIR not set");
        QVERIFY(!openDemo().isEmpty());
        window_->resize(1366, 768);
        QVERIFY(!box()->saveProfile(QStringLiteral("home lab")));
        Config venue = doc()->config();
        auto& green = venue.colors.classes[std::size_t(findColourClass(venue.colors.classes, "green"))].boxes[0];
        green.hMin += 6;
        green.sMin += 25;
        QVERIFY(!doc()->replaceConfig(venue, QStringLiteral("venue")));
        QVERIFY(!box()->saveProfile(QStringLiteral("venue field A")));
        box()->list()->setCurrentRow(rowOf(QStringLiteral("home lab")));
        QVERIFY(!box()->loadProfile(box()->selectedPath()));
        box()->list()->setCurrentRow(rowOf(QStringLiteral("venue field A")));
        QVERIFY(waitForFrame(*window_, 0));
        QVERIFY(!box()->compareProfile(box()->selectedPath()));
        QVERIFY(box()->grab().save(dir + "/colour-profiles.png"));
        QVERIFY(box()->diffView()->grab().save(dir + "/colour-diff.png"));
    }

    void profilesOnTheCommandLine()
    {
        const QString dir = tmp_.filePath(QStringLiteral("cli"));
        QVERIFY(QDir().mkpath(dir));
        const QString config = dir + "/config.yml";
        writeFile(config.toStdString(), serializeConfig(Config{}));
        const tooltest::Run saved = tooltest::runTool(QStringLiteral(OMNITUNE_CALIBRATE),
                                                      {"colours", "--config", config, "--profile-save", "Venue B"});
        QVERIFY2(saved.exitedWith(0), qPrintable(saved.describe()));
        QVERIFY(QFileInfo::exists(dir + "/colour-profiles/venue-b.yml"));

        const tooltest::Run listed =
            tooltest::runTool(QStringLiteral(OMNITUNE_CALIBRATE), {"colours", "--config", config, "--profile-list"});
        QVERIFY2(listed.exitedWith(0), qPrintable(listed.describe()));
        QVERIFY(listed.out.contains("Venue B"));

        // The config's colours change; loading the profile brings the saved ones back.
        Config other;
        other.colors.classes[0].boxes[0].vMax = 33;
        writeFile(config.toStdString(), serializeConfig(other));
        const QString out = dir + "/out.yml";
        const tooltest::Run loaded = tooltest::runTool(QStringLiteral(OMNITUNE_CALIBRATE),
                                                       {"colours", "--config", config, "--profile-load", "Venue B", "--out", out});
        QVERIFY2(loaded.exitedWith(0), qPrintable(loaded.describe()));
        const ConfigLoad back = loadConfig(out.toStdString());
        QVERIFY(back.ok());
        QCOMPARE(back.config.colors.classes, Config{}.colors.classes);

        // A profile that does not exist: refused, naming the file.
        const tooltest::Run missing = tooltest::runTool(QStringLiteral(OMNITUNE_CALIBRATE),
                                                        {"colours", "--config", config, "--profile-load", "nowhere", "--out", out});
        QVERIFY2(missing.refused(), qPrintable(missing.describe()));
        QVERIFY2(missing.err.contains("nowhere.yml"), qPrintable(missing.describe()));
    }
};

QTEST_MAIN(ColourProfilesTest)
#include "app_colour_profiles_test.moc"
