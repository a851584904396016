// Issue 11, "a new camera opens and shows its frames at once": frames of another size than the
// config's are shown with a provisional geometry at once (defaults) or after "Adapt" (a config
// of the user's), and "Set up this camera" starts the guided sequence whose first steps fit
// centre and rim, body and a mask from the frames, each step one Ctrl+Z. The camera: the demo session cropped to 480x480, whose mirror is then
// centred at (240, 240) with its rim at ~240 px and its body at ~48 px.
#include "app/MainWindow.h"
#include "core/ConfigWriter.h"
#include "widgets/CameraSetup.h"
#include "widgets/CameraSetupBar.h"
#include "widgets/ConfigDocument.h"
#include "widgets/GeometryEditor.h"
#include "widgets/ImageView.h"
#include "widgets/PipelineView.h"
#include "widgets/TruthMarker.h"
#include "widgets/NoticeBar.h"
#include "widgets/PipelineRunner.h"
#include "widgets/SetupSequence.h"
#include "WindowTestSupport.h"

#include <opencv2/imgcodecs.hpp>

#include <QPushButton>
#include <QStatusBar>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

// The first `count` demo frames, cropped to the 480x480 middle.
bool writeSquareCamera(const QString& folder, int count)
{
    const QString demo = QStringLiteral(OMNITUNE_SOURCE_DIR "/sessions/demo/frames/");
    for (int i = 0; i < count; ++i) {
        const QString name = QStringLiteral("%1.png").arg(i * 3, 6, 10, QChar('0'));  // spread over the tour
        const cv::Mat frame = cv::imread((demo + name).toStdString());
        if (frame.empty() || !cv::imwrite((folder + "/" + name).toStdString(), frame(cv::Rect(80, 0, 480, 480))))
            return false;
    }
    return true;
}

// Waits (event driven) until the window shows a processed frame under a config for `size`
// (and, with `masked`, one with a mask: the run after the set-up's last step).
bool waitForProcessed(MainWindow& window, cv::Size size, bool masked = false)
{
    QSignalSpy spy(&window, &MainWindow::runShown);
    for (int i = 0; i < 50; ++i) {
        const auto run = window.lastRun();
        if (!window.isProcessing() && run && run->result.ok() && run->error.isEmpty() &&
            run->config.geometry.imageWidth == size.width && run->config.geometry.imageHeight == size.height &&
            (!masked || !run->config.mask.empty()))
            return true;
        spy.wait(200);
    }
    return false;
}

CameraSetupBar* setupBar(MainWindow& window) { return window.findChild<CameraSetupBar*>(); }

}  // namespace

class CameraSetupTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        startWindowTests();
        QVERIFY(dir_.isValid());
        QVERIFY(QDir().mkpath(camera()));
        QVERIFY(writeSquareCamera(camera(), 8));
    }

    // The defaults replace nothing of the user's: the frames show at once, the bar offers set-up.
    void defaultsAdaptAtOnceAndSetUpFits()
    {
        MainWindow window;
        window.cameraSetup()->frameCount = 8;
        window.show();
        QVERIFY(window.openSource(camera()));
        QVERIFY2(waitForProcessed(window, {480, 480}), "the 480x480 frames were not processed under a provisional geometry");
        CameraSetupBar* bar = setupBar(window);
        QVERIFY(bar && bar->isVisible());
        QVERIFY2(bar->text().contains("provisional geometry"), qPrintable(bar->text()));
        QVERIFY(bar->setUpButton()->isVisible());
        QVERIFY(!bar->adaptButton()->isVisible());
        const GeometryOptions provisional = window.document()->config().geometry;
        QCOMPARE(provisional.centerX, 239.5);
        QVERIFY(window.notices()->text().contains("largest circle"));

        QTest::mouseClick(bar->setUpButton(), Qt::LeftButton);
        // The guided sequence: centre and rim, robot body, mask, each applied then Next.
        SetupSequence* steps = window.setupSequence();
        QVERIFY(steps->isVisible());
        QVERIFY(!bar->isVisible());
        QCOMPARE(steps->step(), SetupSequence::CentreRim);
        for (int i = 0; i < 3; ++i) {
            QVERIFY(!steps->nextButton()->isEnabled());  // Next means done; Skip goes on without it
            QTest::mouseClick(steps->applyButton(), Qt::LeftButton);
            QVERIFY2(steps->state(steps->step()) == SetupSequence::StepState::Applied, qPrintable(steps->text()));
            QTest::mouseClick(steps->nextButton(), Qt::LeftButton);
        }
        QCOMPARE(steps->step(), SetupSequence::BallModel);
        const GeometryOptions& g = window.document()->config().geometry;
        QVERIFY2(std::hypot(g.centerX - 240, g.centerY - 240) < 1.5,
                 qPrintable(QString("centre %1, %2; %3").arg(g.centerX).arg(g.centerY).arg(bar->text())));
        QVERIFY2(std::abs(g.innerRadius - 50) < 4, qPrintable(QString::number(g.innerRadius)));
        QVERIFY2(g.outerRadius > 230 && g.outerRadius < 248, qPrintable(QString::number(g.outerRadius)));
        QVERIFY(window.notices()->text().contains("centre ("));
        QVERIFY2(!window.document()->config().mask.empty(), qPrintable(window.notices()->text()));
        QVERIFY(waitForProcessed(window, {480, 480}, true));
        if (qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR"))  // to look at the window after set-up
            window.grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/camera-setup.png");

        // The mask is tinted over every pane: the body is, the field is not.
        {
            const auto tint = window.lastRun()->maskTint;
            QVERIFY(tint);
            QVERIFY(qAlpha(tint->pixel(240, 240)) > 0);
            QCOMPARE(qAlpha(tint->pixel(240, 120)), 0);
        }

        // Each step undoes on its own: mask, body, then centre and rim, then the provisional geometry.
        QUndoStack* undo = window.document()->undoStack();
        undo->undo();
        QVERIFY(window.document()->config().mask.empty());
        const double fittedInner = window.document()->config().geometry.innerRadius;
        undo->undo();
        QVERIFY(window.document()->config().geometry.innerRadius != fittedInner);
        QVERIFY(std::abs(window.document()->config().geometry.centerX - 240) < 1.5);
        undo->undo();
        QCOMPARE(window.document()->config().geometry.centerX, 239.5);
        undo->undo();
        QCOMPARE(window.document()->config().geometry.imageWidth, 640);
        QVERIFY(!window.document()->isDirty());
    }

    // A config of the user's for 640x480 is not replaced unasked; Adapt makes it fit.
    void userConfigIsAdaptedOnlyWhenAsked()
    {
        const QString file = dir_.filePath("robot.yml");
        QVERIFY(!saveConfig(Config{}, file.toStdString(), false));
        MainWindow window;
        window.show();
        QVERIFY(window.openConfig(file));
        QVERIFY(window.openSource(camera()));
        CameraSetupBar* bar = setupBar(window);
        QTRY_VERIFY_WITH_TIMEOUT(bar->isVisible(), 10000);
        QVERIFY2(bar->text().contains("480x480") && bar->text().contains("robot.yml") && bar->text().contains("640x480"),
                 qPrintable(bar->text()));
        QCOMPARE(window.document()->config().geometry.imageWidth, 640);
        QVERIFY(bar->adaptButton()->isVisible());
        QTest::mouseClick(bar->adaptButton(), Qt::LeftButton);
        QCOMPARE(window.document()->config().geometry.imageWidth, 480);
        QVERIFY(window.document()->isDirty());
        QVERIFY(waitForProcessed(window, {480, 480}));
        window.document()->discardChanges();  // closing must not ask
    }

    // Dragging the centre and a radius on a pane, and the Alt+arrow nudge: each one undo step.
    void dragAndNudgeTheGeometry()
    {
        MainWindow window;
        window.resize(1300, 750);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openSource(camera()));
        QVERIFY(waitForProcessed(window, {480, 480}));
        ConfigDocument* doc = window.document();
        const double x0 = doc->config().geometry.centerX, y0 = doc->config().geometry.centerY;

        QTest::keyClick(&window, Qt::Key_G);  // editing mode
        QVERIFY(window.geometryEditor()->isEditing());
        ImageView* pane = window.pipelineView()->pane(PipelineView::Edges);
        const QPoint from = pane->toWidget(QPointF(x0, y0)).toPoint();
        const QPoint to = pane->toWidget(QPointF(x0 + 12, y0 - 8)).toPoint();
        const int steps = doc->undoStack()->count();
        QTest::mousePress(pane, Qt::LeftButton, {}, from);
        QTest::mouseMove(pane, to);
        QTest::mouseRelease(pane, Qt::LeftButton, {}, to);
        const GeometryOptions& g = doc->config().geometry;
        const double moved = pane->toImage(to).x() - pane->toImage(from).x();
        QVERIFY2(std::abs(g.centerX - (x0 + moved)) <= 0.25, qPrintable(QString("centre x %1, moved %2; %3").arg(g.centerX).arg(moved).arg(window.statusBar()->currentMessage())));
        QVERIFY(g.centerY < y0 - 4);
        QCOMPARE(doc->undoStack()->count(), steps + 1);  // the whole drag is one step

        // The outer circle, grabbed on its right side, follows the cursor outwards.
        const double outer = g.outerRadius;
        const QPoint rim = pane->toWidget(QPointF(g.centerX + outer, g.centerY)).toPoint();
        const QPoint out = pane->toWidget(QPointF(g.centerX + outer - 20, g.centerY)).toPoint();
        QTest::mousePress(pane, Qt::LeftButton, {}, rim);
        QTest::mouseMove(pane, out);
        QTest::mouseRelease(pane, Qt::LeftButton, {}, out);
        QVERIFY2(doc->config().geometry.outerRadius < outer - 15, qPrintable(QString::number(doc->config().geometry.outerRadius)));

        // Alt+Right a quarter pixel, Alt+Shift+Up a whole one; plain Right still steps frames.
        const double x1 = doc->config().geometry.centerX, y1 = doc->config().geometry.centerY;
        QTest::keyClick(&window, Qt::Key_Right, Qt::AltModifier);
        QCOMPARE(doc->config().geometry.centerX, x1 + 0.25);
        QTest::keyClick(&window, Qt::Key_Up, Qt::AltModifier | Qt::ShiftModifier);
        QCOMPARE(doc->config().geometry.centerY, y1 - 1.0);
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QCOMPARE(doc->config().geometry.centerX, x0);

        // Truth marking refused here (an image folder holds no truth): the editor keeps the button.
        window.truthMarker()->setMarking(true);
        QVERIFY(!window.truthMarker()->isMarking());
        QVERIFY(window.geometryEditor()->isEditing());
        QTest::keyClick(&window, Qt::Key_G);
        QVERIFY(!window.geometryEditor()->isEditing());
        window.document()->discardChanges();
    }

private:
    QString camera() const { return dir_.filePath("square"); }
    QTemporaryDir dir_;
};

QTEST_MAIN(CameraSetupTest)
#include "app_camera_setup_test.moc"
