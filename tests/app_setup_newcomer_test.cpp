// A newcomer with only the window (issue 11's "done when"): a 480x480 recording of the optics
// simulator's spherical camera on four rods, as a plain image folder, opened with the built-in
// defaults (a 640x480 config). The frames show at once (provisional geometry) with the offer to
// set the camera up; the strip's rim, body and auto-mask steps fit this camera; the ball-model
// step, with no marks yet, says how to get them (Save as session, mark); after Save as session
// and a few marks on the pane the ball model fits; the distance map from clicked floor marks;
// save. OMNITUNE_SCREENSHOT_DIR: a picture at each step (docs/user-guide.md's walk-through).
#include "RemountScene.h"
#include "WindowTestSupport.h"

#include "app/MainWindow.h"
#include "calib/sim/optics/OpticsMeasurement.h"
#include "core/ConfigParser.h"
#include "widgets/BallModelPanel.h"
#include "widgets/ConfigDocument.h"
#include "widgets/DistancePointsModel.h"
#include "widgets/DistancePointsPanel.h"
#include "widgets/PaneEditors.h"
#include "widgets/PipelineView.h"
#include "widgets/SaveAsSession.h"
#include "widgets/SetupSequence.h"
#include "widgets/TruthMarker.h"

#include <QAction>
#include <QApplication>
#include <QMouseEvent>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QtTest>

#include <opencv2/imgcodecs.hpp>

using namespace omnitune;
using namespace omnitune::remount;
using namespace omnitune::testing;

class SetupNewcomerTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;

private slots:
    void initTestCase()
    {
        startWindowTests();
    }

    void squareSphericalCameraFromFirstFrameToSavedConfig()
    {
        OpticsCell cell;
        cell.mirror = OpticsMirror::Spherical;
        cell.image = {480, 480};
        cell.distractors = OpticsDistractors::RodsOcclusion;
        cell.frames = 30;
        const CatadioptricCamera camera(opticsCellCameraParams(cell));
        const OpticsRenderer renderer(camera);
        const Tour tour = renderTour(cell, renderer);
        const QString images = tmp_.filePath("recording");
        QDir().mkpath(images);
        for (std::size_t i = 0; i < tour.frames.size(); ++i)
            QVERIFY(cv::imwrite(QString("%1/%2.png").arg(images).arg(i, 4, 10, QChar('0')).toStdString(), tour.frames[i]));

        MainWindow window;
        QVERIFY(showActive(window));
        window.cameraSetup()->frameCount = kSetupTestFrames;
        const auto shoot = [&](const QString& name) {
            if (!qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR")) return;
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            if (window.lastRun()) waitForFrame(window, window.lastRun()->frameIndex);
            window.grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/newcomer-" + name + ".png");
        };
        QVERIFY(window.openSource(images));
        QVERIFY(waitForFrame(window, 0));  // shown at once: the defaults were adapted to 480x480
        ConfigDocument* doc = window.document();
        QCOMPARE(doc->config().geometry.imageWidth, 480);
        shoot("1-opened");
        auto* bar = window.findChild<QWidget*>("cameraSetup");
        QVERIFY(bar && bar->isVisible());
        QPushButton* setUp = nullptr;
        for (auto* b : bar->findChildren<QPushButton*>())
            if (b->text() == "Set up this camera") setUp = b;
        QVERIFY(setUp && setUp->isVisible());
        QTest::mouseClick(setUp, Qt::LeftButton);
        SetupSequence* seq = window.setupSequence();
        QVERIFY(seq->isVisible());
        const auto applyStep = [&](SetupSequence::Step step, const QString& shot) {
            QCOMPARE(seq->step(), step);
            QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
            QVERIFY2(seq->state(step) == SetupSequence::StepState::Applied, qPrintable(seq->text()));
            shoot(shot);
            QTest::mouseClick(seq->nextButton(), Qt::LeftButton);
        };
        applyStep(SetupSequence::CentreRim, "2-rim");
        const cv::Point2d axis = fieldCentre(camera);
        QVERIFY2(std::hypot(doc->config().geometry.centerX - axis.x, doc->config().geometry.centerY - axis.y) < 1.5,
                 qPrintable(QString("%1, %2 vs %3, %4").arg(doc->config().geometry.centerX).arg(doc->config().geometry.centerY)
                                .arg(axis.x).arg(axis.y)));
        applyStep(SetupSequence::Body, "3-body");
        applyStep(SetupSequence::Mask, "4-mask");
        QVERIFY(!doc->config().mask.empty());

        // The ball model: an image folder has no marks; the step says what to do.
        QCOMPARE(seq->step(), SetupSequence::BallModel);
        QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
        QVERIFY(seq->state(SetupSequence::BallModel) == SetupSequence::StepState::Open);
        shoot("5-ball-model-no-marks");
        QVERIFY2(seq->text().contains("saved as a session"), qPrintable(seq->text()));
        // So: File > Save as session. The edits go with it, unasked; the strip stays at its step.
        const QString session = tmp_.filePath("recording-session");
        window.findChild<SaveAsSession*>()->setFolderAsker([&](const QString&) { return session; });
        window.findChild<QAction*>("saveAsSession")->trigger();
        QVERIFY(waitForFrame(window, 0));
        QVERIFY(!doc->isDirty());
        QCOMPARE(QFileInfo(doc->path()).absoluteFilePath(), QFileInfo(session + "/config.yml").absoluteFilePath());
        QVERIFY(!doc->config().mask.empty());
        shoot("6-saved-as-session");
        QVERIFY(seq->isVisible());
        QCOMPARE(seq->step(), SetupSequence::BallModel);

        // Marking on the acquired pane (T): each ball's centre pressed, its radius dragged; N for a
        // frame without one. Each mark goes on to the next frame.
        QTest::keyClick(&window, Qt::Key_T);
        QVERIFY(window.truthMarker()->isMarking());
        ImageView* pane = window.pipelineView()->pane(PipelineView::Acquired);
        for (int i = 0; i < int(tour.frames.size()); ++i) {
            QVERIFY(waitForFrame(window, i));
            const TruthRow& t = tour.truth.at(i);
            if (!t.ballVisible) {
                QTest::keyClick(&window, Qt::Key_N);
                continue;
            }
            // The move is sent to the pane itself: QTest::mouseMove goes through the cursor, which
            // the offscreen platform delivers without the button held (see app/mask_editor).
            const QPoint a = pane->toWidget(QPointF(t.px, t.py)).toPoint();
            const QPoint b = pane->toWidget(QPointF(t.px + t.radiusPx, t.py)).toPoint();
            QTest::mousePress(pane, Qt::LeftButton, {}, a);
            QMouseEvent move(QEvent::MouseMove, QPointF(b), QPointF(pane->mapToGlobal(b)), Qt::NoButton, Qt::LeftButton,
                             Qt::NoModifier);
            QApplication::sendEvent(pane, &move);
            QTest::mouseRelease(pane, Qt::LeftButton, {}, b);
        }
        QTest::keyClick(&window, Qt::Key_T);
        QVERIFY(!window.truthMarker()->isMarking());
        QVERIFY(int(window.ballModel()->samples().size()) >= 20);
        QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
        QVERIFY2(seq->state(SetupSequence::BallModel) == SetupSequence::StepState::Applied, qPrintable(seq->text()));
        shoot("7-ball-model");
        QVERIFY2(window.ballModel()->lastFit()->rmsPx < 1.5, qPrintable(window.ballModel()->status()));
        QTest::mouseClick(seq->nextButton(), Qt::LeftButton);

        // The distance map: floor marks clicked, their taped distances typed, the camera height.
        QCOMPARE(seq->step(), SetupSequence::DistanceMap);
        const CameraMeasurements marks = measureOpticsCamera(renderer);
        DistancePointsPanel* points = window.paneEditors()->distances();
        points->setDistanceAsker([&camera](QPointF p) -> std::optional<double> {
            const auto ray = camera.rayAt(p.x(), p.y());
            if (!ray || ray->direction[2] >= 0) return std::nullopt;
            const double k = -ray->origin[2] / ray->direction[2];
            return std::hypot(ray->origin[0] + k * ray->direction[0], ray->origin[1] + k * ray->direction[1]);
        });
        QTest::mouseClick(points->findChild<QPushButton*>("addDistancePoints"), Qt::LeftButton);
        for (const CalibrationPoint& m : marks.points)
            QTest::mouseClick(pane, Qt::LeftButton, {}, pane->toWidget(QPointF(m.xPx, m.yPx)).toPoint());
        auto* height = points->findChild<QDoubleSpinBox*>("viewpointHeight");
        height->selectAll();
        QTest::keyClicks(height, QString::number(marks.viewpointHeight, 'f', 3));
        QTest::keyClick(height, Qt::Key_Enter);
        QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
        // The spherical mirror's metres per pixel run away near the rim: no polynomial rises over
        // all the marks, so the fit is the marks' own table, and says so.
        QVERIFY2(seq->state(SetupSequence::DistanceMap) == SetupSequence::StepState::Applied, qPrintable(seq->text()));
        QVERIFY2(points->status().contains("RMS"), qPrintable(points->status()));
        shoot("8-distance-map");
        QTest::mouseClick(seq->nextButton(), Qt::LeftButton);
        QTest::mouseClick(seq->skipButton(), Qt::LeftButton);  // colours: the defaults serve this carpet
        QCOMPARE(seq->step(), SetupSequence::Save);
        QTest::mouseClick(seq->applyButton(), Qt::LeftButton);
        QVERIFY2(seq->state(SetupSequence::Save) == SetupSequence::StepState::Applied, qPrintable(seq->text()));
        shoot("9-saved");
        QVERIFY(!doc->isDirty());
        const ConfigLoad saved = loadConfig((session + "/config.yml").toStdString());
        QVERIFY(saved.ok());
        QCOMPARE(saved.config.geometry.imageWidth, 480);
        QVERIFY(!saved.config.mask.empty());
        qInfo().noquote() << "ball model:" << window.ballModel()->status() << "| distance map:" << points->status();
    }
};

QTEST_MAIN(SetupNewcomerTest)
#include "app_setup_newcomer_test.moc"
