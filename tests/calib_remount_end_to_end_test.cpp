// Issue 11's "done when", on the optics simulator: a camera calibrated from its measurements
// gives a detection ratio R0 and a range error E0 on a tour; the camera is then remounted
// (principal point moved, mirror 1 cm higher, support rods turned) and the old config no longer
// serves. The remounted camera is recalibrated with the set-up sequence's own calib/ functions
// in its order — centre and rim and robot body from frames of the robot turning, the painted
// mask (the auto-mask refuses this simulator's plain carpet), the ball model from the tour's
// truth marks, the distance map from floor marks the simulator knows — and the range error
// comes back to within 5 cm of E0, the ratio to within 2 points of the remounted camera's own
// full calibration (calibrateFromMeasurements).
//
// It calls the functions the window's steps call (CameraSetup, BallModelPanel and
// DistancePointsPanel are thin over them), not the window itself: rendering and the runs over
// the tour stay under a minute that way.
#include "calib/eval/Evaluation.h"
#include "calib/fit/BallModelFit.h"
#include "calib/fit/CalibrationPointsCsv.h"
#include "calib/fit/DistanceMapFit.h"
#include "calib/fit/MeasuredCalibration.h"
#include "calib/fit/MirrorFit.h"
#include "calib/mask/AutoMask.h"
#include "calib/sim/optics/OpticsCell.h"
#include "calib/sim/optics/OpticsMeasurement.h"
#include "core/ColorLut.h"
#include "core/Pipeline.h"

#include <QtTest>

#include <cmath>

using namespace omnitune;

namespace {

constexpr int kFrames = 40;

struct Tour {
    std::vector<cv::Mat> frames;
    std::map<int, TruthRow> truth;
};

Tour renderTour(const OpticsCell& cell, const OpticsRenderer& renderer)
{
    Tour t;
    for (int i = 0; i < cell.frames; ++i) {
        OpticsTruth truth;
        t.frames.push_back(renderer.render(opticsCellScene(cell, i, renderer), &truth));
        t.truth[i] = toTruthRow(truth, i, cell.ballPresent);
    }
    return t;
}

EvaluationRow evaluateTour(const Tour& tour, const Config& config)
{
    Pipeline pipeline(config);
    std::vector<FrameOutcome> outcomes;
    PipelineResult result;
    for (int i = 0; i < int(tour.frames.size()); ++i) {
        pipeline.process(tour.frames[i], PixelFormat::Bgr8, result);
        outcomes.push_back(outcomeOf(i, result));
    }
    return evaluate(outcomes, tour.truth);
}

// The same camera after a remount: the camera shifted under the mirror, the mirror 1 cm
// higher on its rods, the rods turned 20 degrees about the robot's axis.
CatadioptricCameraParams remounted(CatadioptricCameraParams p)
{
    p.principal += cv::Point2d(7.0, -5.0);
    const double rise = 0.01;
    p.vertexAboveCamera += rise;
    p.measuredViewpointHeight += rise;
    const double a = 20.0 * CV_PI / 180.0, c = std::cos(a), s = std::sin(a);
    for (SupportRod& rod : p.rods) {
        for (cv::Point3d* end : {&rod.bottom, &rod.top})
            *end = cv::Point3d(c * end->x - s * end->y, s * end->x + c * end->y, end->z);
        rod.top.z += rise;
    }
    p.name += "-remounted";
    return p;
}

}  // namespace

class RemountEndToEndTest : public QObject {
    Q_OBJECT
private slots:
    void remountedCameraComesBack()
    {
        // A hyperbolic 640x480 camera on three support rods; the tour's balls are clear of them.
        OpticsCell cell;
        cell.frames = kFrames;
        CatadioptricCameraParams mount = opticsCellCameraParams(cell);
        mount.rods = hyperbolicCameraParams(cell.image, 3).rods;
        const CatadioptricCamera originalCamera(mount);
        const OpticsRenderer originalRenderer(originalCamera);
        const MeasuredCalibration calibration = calibrateFromMeasurements(Config{}, measureOpticsCamera(originalRenderer));
        QVERIFY2(calibration.ok(), calibration.error ? calibration.error->c_str() : "");
        const Config c0 = calibration.config;
        const Tour before = renderTour(cell, originalRenderer);
        const EvaluationRow r0 = evaluateTour(before, c0);
        QVERIFY2(r0.detectionRatioPct > 50, qPrintable(QString::number(r0.detectionRatioPct)));

        const CatadioptricCamera camera(remounted(mount));
        const OpticsRenderer renderer(camera);
        const Tour after = renderTour(cell, renderer);
        const EvaluationRow stale = evaluateTour(after, c0);

        // What the team records at the venue: the robot turning on the field (the frames the
        // set-up reads), floor marks at measured distances.
        const CameraMeasurements venue = measureOpticsCamera(renderer);
        OpticsCell busy = cell;  // other robots and people move around ours while it turns
        busy.distractors = OpticsDistractors::RobotsFeetShadow;
        busy.frames = 12;
        const std::vector<cv::Mat> turning = renderTour(busy, renderer).frames;
        // Centre and rim, then the body (the set-up's first two steps).
        const MirrorFitResult mirror = fitMirror(turning, c0);
        QVERIFY2(mirror.ok(), mirror.error ? mirror.error->message.c_str() : "");
        Config c1 = mirror.config;
        const cv::Point2d centre(c1.geometry.centerX, c1.geometry.centerY);
        QVERIFY2(cv::norm(centre - cv::Point2d(c0.geometry.centerX, c0.geometry.centerY)) > 4,
                 "the remount should move the centre");
        // The mask: the auto-mask finds nothing to tell from the simulator's plain carpet (it
        // refuses, "nothing but carpet moved"), so the mask is the one painted over rods and
        // body, as the mask step's editor or Import mask... gives it.
        QVERIFY(!autoMask(turning, c1.geometry, ColorLut(c1.colors)).ok());
        QVERIFY(!venue.mask.empty());
        c1.mask = venue.mask;
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
        // The remounted camera's best: its own full calibration from everything measured.
        const EvaluationRow ref = evaluateTour(after, calibrateFromMeasurements(Config{}, venue).config);
        const QString numbers = QString("original R0 %1 %, E0 %2 m; stale config %3 %, %4 m; set-up %5 %, %6 m; "
                                        "full calibration of the remounted camera %7 %, %8 m")
                                    .arg(r0.detectionRatioPct).arg(r0.meanErrorM).arg(stale.detectionRatioPct)
                                    .arg(stale.meanErrorM).arg(r1.detectionRatioPct).arg(r1.meanErrorM)
                                    .arg(ref.detectionRatioPct).arg(ref.meanErrorM);
        qInfo().noquote() << numbers;
        // The old config no longer serves the remounted camera.
        QVERIFY2(stale.detectionRatioPct < ref.detectionRatioPct - 10 || stale.meanErrorM > ref.meanErrorM + 0.1,
                 qPrintable(numbers));
        // The set-up brings it back: the range within 5 cm of the original calibration's, the
        // ratio within 2 points of what this camera gives at best. (Not of the original's ratio:
        // even the remounted camera's own full calibration finds fewer balls on its tour, 69 %
        // against 81 %; why is not known yet.)
        QVERIFY2(r1.meanErrorM <= r0.meanErrorM + 0.05, qPrintable(numbers));
        QVERIFY2(r1.meanErrorM <= ref.meanErrorM + 0.05, qPrintable(numbers));
        QVERIFY2(r1.detectionRatioPct >= ref.detectionRatioPct - 2.0, qPrintable(numbers));
    }
};

QTEST_GUILESS_MAIN(RemountEndToEndTest)
#include "calib_remount_end_to_end_test.moc"
