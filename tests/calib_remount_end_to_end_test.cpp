// Issue 11's "done when", on the optics simulator: a camera calibrated from its measurements
// gives a detection ratio R0 and a range error E0 on a tour; the camera is then remounted
// (principal point moved, mirror 1 cm higher, support rods turned) and the old config no longer
// serves. The remounted camera is recalibrated with the set-up sequence's own calib/ functions
// in its order — centre and rim and robot body from frames of the robot turning, the auto-mask
// from the same frames, the ball model from the tour's truth marks, the distance map from
// floor marks the simulator knows — and the range error comes back to within 5 cm of E0 and the
// ratio to within 2 points of R0 over the balls the remounted ring can hold.
//
// Why not R0 over the whole tour: the raised mirror's image is 10 % smaller, so its ring reaches
// 3.35 m onto the field instead of 4.32 m, and past that the ball is out of the processed area
// or outside the mirror (calib/remount_diagnosis measures it per miss cause). No calibration
// brings those balls back; within the reach both cameras find the same share.
//
// It calls the functions the window's steps call (CameraSetup, BallModelPanel and
// DistancePointsPanel are thin over them); app/setup_remount drives the window itself.
#include "RemountScene.h"

#include "calib/fit/BallModelFit.h"
#include "calib/fit/CalibrationPointsCsv.h"
#include "calib/fit/DistanceMapFit.h"
#include "calib/fit/MeasuredCalibration.h"
#include "calib/fit/MirrorFit.h"
#include "calib/mask/AutoMask.h"
#include "calib/sim/optics/OpticsMeasurement.h"
#include "core/ColorLut.h"

#include <QtTest>

#include <cmath>

using namespace omnitune;
using namespace omnitune::remount;

class RemountEndToEndTest : public QObject {
    Q_OBJECT
private slots:
    void remountedCameraComesBack()
    {
        // A hyperbolic 640x480 camera on three support rods; the tour's balls are clear of them.
        OpticsCell cell = tourCell();
        cell.frames = 120;  // one ball is under a point within the remounted reach
        const CatadioptricCamera originalCamera(originalMount(cell));
        const OpticsRenderer originalRenderer(originalCamera);
        const MeasuredCalibration calibration = calibrateFromMeasurements(Config{}, measureOpticsCamera(originalRenderer));
        QVERIFY2(calibration.ok(), calibration.error ? calibration.error->c_str() : "");
        const Config c0 = calibration.config;
        const Tour before = renderTour(cell, originalRenderer);
        const EvaluationRow r0 = evaluateTour(before, c0);
        QVERIFY2(r0.detectionRatioPct > 50, qPrintable(QString::number(r0.detectionRatioPct)));

        const CatadioptricCamera camera(remounted(originalMount(cell)));
        const OpticsRenderer renderer(camera);
        const Tour after = renderTour(cell, renderer);
        const EvaluationRow stale = evaluateTour(after, c0);

        // What the team records at the venue: the robot turning on the field (the frames the
        // set-up reads), floor marks at measured distances.
        const CameraMeasurements venue = measureOpticsCamera(renderer);
        OpticsCell busy = cell;  // other robots and people move around ours while it turns
        busy.distractors = OpticsDistractors::RobotsFeetShadow;
        busy.frames = 8;
        const std::vector<cv::Mat> turning = renderTour(busy, renderer).frames;
        // Centre and rim, then the body (the set-up's first two steps).
        const MirrorFitResult mirror = fitMirror(turning, c0);
        QVERIFY2(mirror.ok(), mirror.error ? mirror.error->message.c_str() : "");
        Config c1 = mirror.config;
        const cv::Point2d centre(c1.geometry.centerX, c1.geometry.centerY);
        QVERIFY2(cv::norm(centre - cv::Point2d(c0.geometry.centerX, c0.geometry.centerY)) > 4,
                 "the remount should move the centre");
        // The mask: the auto-mask from the same frames (body and rods stay, the field moves).
        const AutoMaskResult mask = autoMask(turning, c1.geometry, ColorLut(c1.colors));
        QVERIFY2(mask.ok(), mask.ok() ? "" : mask.error->message.c_str());
        c1.mask = mask.fit.mask;
        // The ball model from the tour's marks.
        const BallModelFitResult ball = fitBallModel(ballSamplesFromTruth(after.truth, centre));
        QVERIFY2(ball.ok(), ball.error ? ball.error->message.c_str() : "");
        applyBallModelFit(ball.fit, c1.ball);
        // The distance map from floor marks at measured distances.
        const DistanceMapFitResult map = fitDistanceMap(toDistancePoints(venue.points, centre));
        QVERIFY2(map.ok(), map.error ? map.error->message.c_str() : "");
        applyDistanceMapFit(map.fit, c1.distanceMap);
        if (venue.viewpointHeight > 0) c1.distanceMap.viewpointHeight = venue.viewpointHeight;  // the tape measure

        const EvaluationRow r1 = evaluateTour(after, c1);
        // Over the balls the remounted camera's ring can hold, on both tours (same positions).
        const double reach = ringReachM(after, c1.geometry);
        const EvaluationRow r0in = evaluateTour(within(before, reach), c0);
        const EvaluationRow r1in = evaluateTour(within(after, reach), c1);
        QString numbers =
            QString("original R0 %1 %, E0 %2 m; stale config %3 %, %4 m; set-up %5 %, %6 m; within the remounted "
                    "reach %7 m: original %8 %, set-up %9 %")
                .arg(r0.detectionRatioPct).arg(r0.meanErrorM).arg(stale.detectionRatioPct).arg(stale.meanErrorM)
                .arg(r1.detectionRatioPct).arg(r1.meanErrorM).arg(reach).arg(r0in.detectionRatioPct)
                .arg(r1in.detectionRatioPct);
        numbers += QString("; range error within the reach: original %1 m, set-up %2 m; false detections %3 -> %4")
                       .arg(r0in.meanErrorM).arg(r1in.meanErrorM).arg(r0.falsePositives).arg(r1.falsePositives);
        qInfo().noquote() << numbers;
        // The old config no longer serves the remounted camera.
        QVERIFY2(stale.detectionRatioPct < r1.detectionRatioPct - 10 || stale.meanErrorM > r1.meanErrorM + 0.1,
                 qPrintable(numbers));
        // The set-up brings it back: the range within 5 cm of the original calibration's, the
        // ratio within 2 points of the original's over the balls within the remounted reach.
        // Range accuracy over the same balls as the ratio (meanErrorM counts a false detection's
        // metres too: one rim artefact 6 m off moves the whole tour's mean by 8 cm); false
        // detections are bounded on their own, over the whole tour.
        QVERIFY2(r1in.meanErrorM <= r0in.meanErrorM + 0.05, qPrintable(numbers));
        QVERIFY2(r1.falsePositives <= r0.falsePositives + 1, qPrintable(numbers));
        QVERIFY2(r1in.withBall >= 60, qPrintable(numbers));
        QVERIFY2(r1in.detectionRatioPct >= r0in.detectionRatioPct - 2.0, qPrintable(numbers));
    }
};

QTEST_GUILESS_MAIN(RemountEndToEndTest)
#include "calib_remount_end_to_end_test.moc"
