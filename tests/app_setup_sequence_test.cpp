// The guided set-up (issue 11), offscreen, driving the real window on a copy of the demo
// session: Camera > Set up this camera shows the strip; every step is applied through its
// button (centre and rim, robot body, auto-mask, ball model from the session's truth marks,
// distance map from loaded points, auto colours, save) and each applied step is exactly one
// undo command; Back returns to a step, Skip goes on without changing the config, and the
// saved file holds what the steps fitted.
#include "app/MainWindow.h"
#include "core/ConfigParser.h"
#include "core/DistanceMap.h"
#include "widgets/BallModelPanel.h"
#include "widgets/CurveFitPlot.h"
#include "widgets/DistancePointsPanel.h"
#include "widgets/MaskEditor.h"
#include "widgets/PaneEditors.h"
#include "widgets/GeometryEditor.h"
#include "widgets/SetupSequence.h"
#include "WindowTestSupport.h"

#include <QAction>
#include <QDockWidget>
#include <QPushButton>
#include <QtTest>

#include <fstream>

using namespace omnitune;
using namespace omnitune::testing;

class SetupSequenceTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;

    // POINTS.csv from the demo camera's own distance map, as a tape measure would give it.
    QString writePoints(const Config& config)
    {
        const QString path = tmp_.filePath("points.csv");
        std::ofstream out(path.toStdString());
        out << "radius_px,distance_m\n";
        const DistanceMap map(config.distanceMap);
        for (double r = 40; r <= 200; r += 20) out << r << "," << map.toGround(r) << "\n";
        return path;
    }

private slots:
    void initTestCase()
    {
        startWindowTests();
    }

    void everyStepAppliesOneUndoCommand()
    {
        const QString session = tmp_.filePath("demo");
        QVERIFY(copyDemo(session));
        MainWindow window;
        QVERIFY(openSetupWindow(window, session));
        ConfigDocument* doc = window.document();
        const Config original = doc->config();
        QUndoStack* undo = doc->undoStack();

        SetupSequence* seq = window.setupSequence();
        QVERIFY(!seq->isVisible());
        window.findChild<QAction*>("setUpCamera")->trigger();
        QVERIFY(seq->isVisible());
        QCOMPARE(seq->step(), SetupSequence::CentreRim);
        QVERIFY(!seq->backButton()->isEnabled());

        // OMNITUNE_SCREENSHOT_DIR set: the window at a few steps, for docs/user-guide.md.
        const auto shoot = [&](const QString& name) {
            if (!qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR")) return;
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);  // the strip just shown, laid out
            if (waitForFrame(window, window.lastRun()->frameIndex))
                window.grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/" + name + ".png");
        };
        shoot("setup-1-start");
        const auto applyStep = [&](SetupSequence::Step step) {
            const int before = undo->count();
            QString text;
            const QString fault = applySetupStep(*seq, step, &text);
            QVERIFY2(fault.isEmpty(), qPrintable(fault));
            QCOMPARE(undo->count(), before + 1);
            QVERIFY2(text.contains("Done:"), qPrintable(text));
        };

        // Centre and rim: fitted near the demo's own, and the circles are draggable.
        applyStep(SetupSequence::CentreRim);
        QVERIFY(window.geometryEditor()->isEditing());
        const GeometryOptions& g = doc->config().geometry;
        QVERIFY2(std::hypot(g.centerX - original.geometry.centerX, g.centerY - original.geometry.centerY) < 1.5,
                 qPrintable(QString("%1, %2").arg(g.centerX).arg(g.centerY)));

        // Back to it and forward again changes nothing.
        QTest::mouseClick(seq->backButton(), Qt::LeftButton);
        QCOMPARE(seq->step(), SetupSequence::CentreRim);
        QVERIFY(seq->nextButton()->isEnabled());  // applied already
        const int undoBefore = undo->count();
        QTest::mouseClick(seq->nextButton(), Qt::LeftButton);
        QCOMPARE(undo->count(), undoBefore);

        applyStep(SetupSequence::Body);
        const int beforeMask = undo->count();
        QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
        QCOMPARE(undo->count(), beforeMask + 1);
        shoot("setup-3-mask");
        QVERIFY2(!doc->config().mask.empty(), qPrintable(seq->text()));
        QVERIFY(window.paneEditors()->mask()->isEditing());  // correct it with the brush
        QTest::mouseClick(seq->nextButton(), Qt::LeftButton);

        // Ball model: the panel is shown with the truth marks as samples; the fit is plotted.
        QCOMPARE(seq->step(), SetupSequence::BallModel);
        QVERIFY(!window.paneEditors()->mask()->isEditing());
        auto* ballDock = window.findChild<QDockWidget*>("ballModel");
        QVERIFY(ballDock && ballDock->isVisible());
        QCOMPARE(int(window.ballModel()->samples().size()), 24);
        applyStep(SetupSequence::BallModel);
        QVERIFY(window.ballModel()->lastFit());
        QCOMPARE(window.ballModel()->plot()->plotData().residuals.size(), std::size_t(24));
        QVERIFY(window.ballModel()->plot()->plotData().summary.contains("RMS"));
        QTest::mouseClick(seq->backButton(), Qt::LeftButton);  // the ball-model step with its plot, for the picture
        shoot("setup-4-ball-model");
        QTest::mouseClick(seq->nextButton(), Qt::LeftButton);
        QVERIFY(doc->config().ball.c0 != original.ball.c0 || doc->config().ball.c1 != original.ball.c1);

        // Distance map: the panel is shown; without points the step says so and changes nothing.
        QCOMPARE(seq->step(), SetupSequence::DistanceMap);
        QVERIFY(window.findChild<QDockWidget*>("distanceMap")->isVisible());
        const int noPoints = undo->count();
        QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
        QCOMPARE(undo->count(), noPoints);
        QVERIFY(seq->state(SetupSequence::DistanceMap) == SetupSequence::StepState::Open);
        QVERIFY2(seq->text().contains("Not done"), qPrintable(seq->text()));
        QVERIFY(!seq->nextButton()->isEnabled());
        QVERIFY(window.paneEditors()->distances()->loadPoints(writePoints(original)));
        applyStep(SetupSequence::DistanceMap);

        // Colours: skipped, so the classes stay as they were.
        QCOMPARE(seq->step(), SetupSequence::Colours);
        QVERIFY(window.findChild<QDockWidget*>("colours")->isVisible());
        const int beforeSkip = undo->count();
        QTest::mouseClick(seq->skipButton(), Qt::LeftButton);
        QCOMPARE(undo->count(), beforeSkip);
        QVERIFY(seq->state(SetupSequence::Colours) == SetupSequence::StepState::Skipped);
        // ... then back and applied after all.
        QTest::mouseClick(seq->backButton(), Qt::LeftButton);
        applyStep(SetupSequence::Colours);

        // Save: the file holds what the steps fitted; Finish closes the strip.
        QCOMPARE(seq->step(), SetupSequence::Save);
        QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
        QVERIFY2(seq->state(SetupSequence::Save) == SetupSequence::StepState::Applied, qPrintable(seq->text()));
        QVERIFY(!doc->isDirty());
        const ConfigLoad saved = loadConfig((session + "/config.yml").toStdString());
        QVERIFY(saved.ok());
        QCOMPARE(saved.config.geometry.centerX, doc->config().geometry.centerX);
        QCOMPARE(saved.config.ball.c1, doc->config().ball.c1);
        QVERIFY(!saved.config.mask.empty());
        QCOMPARE(seq->nextButton()->text(), QStringLiteral("Finish"));
        QSignalSpy finished(seq, &SetupSequence::finished);
        QTest::mouseClick(seq->nextButton(), Qt::LeftButton);
        QCOMPARE(finished.count(), 1);
        QVERIFY(!seq->isVisible());

        // Seven undo commands: rim, body, mask, ball model, distance map, colours (Save adds none).
        for (int i = 0; i < 6; ++i) undo->undo();
        QCOMPARE(doc->config().geometry.centerX, original.geometry.centerX);
        QVERIFY(doc->config().mask.empty() == original.mask.empty());
        QCOMPARE(doc->config().ball.c1, original.ball.c1);
    }

    void ballModelPanelRefusesTooFewSamples()
    {
        const QString session = tmp_.filePath("few");
        QVERIFY(copyDemo(session));
        {  // two marks only
            std::ifstream in((session + "/truth.csv").toStdString());
            std::string header, a, b;
            std::getline(in, header);
            std::getline(in, a);
            std::getline(in, b);
            in.close();
            std::ofstream((session + "/truth.csv").toStdString()) << header << "\n" << a << "\n" << b << "\n";
        }
        MainWindow window;
        QVERIFY(openSetupWindow(window, session));
        const Config before = window.document()->config();
        BallModelPanel* panel = window.ballModel();
        QCOMPARE(int(panel->samples().size()), 2);
        const SetupStepOutcome out = panel->apply();
        QVERIFY(!out.ok);
        QVERIFY2(out.text.contains("at least"), qPrintable(out.text));
        QCOMPARE(window.document()->config().ball.c0, before.ball.c0);
        QVERIFY(!window.document()->isDirty());
    }
};

QTEST_MAIN(SetupSequenceTest)
#include "app_setup_sequence_test.moc"
