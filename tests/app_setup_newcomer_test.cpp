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

#include <QAction>
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
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        isolateRecoveryFiles();
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
        window.cameraSetup()->frameCount = 8;
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
        qInfo().noquote() << "after Save as session: strip visible" << seq->isVisible() << "step" << seq->step();
    }
};

QTEST_MAIN(SetupNewcomerTest)
#include "app_setup_newcomer_test.moc"
