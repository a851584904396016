// Automatic camera calibration (thesis ref. [31]) end to end on the simulated camera: from dark,
// bright and tinted starts the MSV reaches 2.5 +- 0.3 and the white card turns neutral within 30
// iterations; a feature held at its limit ends the run "not converged" with a reason naming it;
// revert writes back the settings from before. Plus the MSV itself on known histograms.
#include "calib/camera/CameraAutoCalibration.h"
#include "calib/camera/MeanSampleValue.h"
#include "calib/camera/SimulatedCamera.h"
#include "core/Config.h"
#include "core/Geometry.h"

#include <QtTest>

using namespace omnitune;

Q_DECLARE_METATYPE(omnitune::SimulatedStart)

namespace {

cv::Mat ringMask()
{
    const Config config;
    return Geometry(config.geometry, config.mask).usedMask().clone();
}

SimulatedCameraOptions cameraOptions(SimulatedStart start)
{
    SimulatedCameraOptions o;
    o.start = start;
    o.poses = 3;
    return o;
}

}  // namespace

class CameraAutoTest : public QObject {
    Q_OBJECT

private slots:
    void msvOfKnownHistograms()
    {
        QCOMPARE(meanSampleValue({10, 0, 0, 0, 0}), 1.0);
        QCOMPARE(meanSampleValue({0, 0, 0, 0, 10}), 5.0);
        QCOMPARE(meanSampleValue({1, 1, 1, 1, 1}), 3.0);
        QCOMPARE(meanSampleValue({0, 0, 0, 0, 0}), 0.0);
        // Grey levels 0..255 fall in regions of width 256/5: 51 is region 0, 52 region 1, 255 region 4.
        cv::Mat grey(1, 4, CV_8UC1);
        grey.at<uchar>(0, 0) = 51;
        grey.at<uchar>(0, 1) = 52;
        grey.at<uchar>(0, 2) = 255;
        grey.at<uchar>(0, 3) = 0;
        const auto h = regionHistogram(grey, {}, 5);
        QCOMPARE(h, (std::vector<double>{2, 1, 0, 0, 1}));
        cv::Mat mask = cv::Mat::zeros(1, 4, CV_8UC1);
        mask.at<uchar>(0, 2) = 255;
        QCOMPARE(meanSampleValue(regionHistogram(grey, mask, 5)), 5.0);
    }

    void regionsOutsideTheFrameAreNamed()
    {
        CameraAutoOptions o;
        o.whiteX = 630;
        CameraMeasurement m;
        const auto why = measureCameraFrame(cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(100)), {}, o, m);
        QVERIFY(why);
        QVERIFY2(why->find("camera_auto.white_") != std::string::npos && why->find("640x480") != std::string::npos,
                 why->c_str());
    }

    void convergesFromBadStarts_data()
    {
        QTest::addColumn<SimulatedStart>("start");
        QTest::newRow("dark") << SimulatedStart::Dark;
        QTest::newRow("bright") << SimulatedStart::Bright;
        QTest::newRow("tinted") << SimulatedStart::Tinted;
    }

    void convergesFromBadStarts()
    {
        QFETCH(SimulatedStart, start);
        SimulatedCamera cam(cameraOptions(start));
        QVERIFY(!cam.open());
        const CameraAutoOptions o;
        const cv::Mat mask = ringMask();

        // Badly set at first: the first measurement is far off.
        CameraAutoCalibration calibration(cam, o, mask);
        QVERIFY(!calibration.begin());
        CameraAutoIteration first;
        QVERIFY(!calibration.step(first));
        const bool wasBad = std::abs(first.measured.msv - 2.5) > 0.5 || std::abs(first.measured.u - 128) > 10 ||
                            std::abs(first.measured.v - 128) > 10;
        QVERIFY2(wasBad, formatCameraMeasurement(first.measured).c_str());

        CameraAutoIteration last = first;
        while (calibration.state() == CameraAutoState::Running) QVERIFY(!calibration.step(last));
        QVERIFY2(calibration.state() == CameraAutoState::Converged, calibration.reason().c_str());
        QVERIFY2(calibration.iterations() <= 30, qPrintable(QString::number(calibration.iterations())));
        QVERIFY(std::abs(last.measured.msv - 2.5) <= 0.3);
        QVERIFY(std::abs(last.measured.u - 128) <= o.chromaTolerance);
        QVERIFY(std::abs(last.measured.v - 128) <= o.chromaTolerance);
        QVERIFY(std::abs(last.measured.black - o.blackTarget) <= o.blackTolerance);

        // What the camera delivers afterwards stays there (the loop did not stop on a lucky frame).
        Frame f;
        for (int i = 0; i < 4; ++i) QVERIFY(!cam.grab(f));
        CameraMeasurement after;
        QVERIFY(!measureCameraFrame(f.image, mask, o, after));
        QVERIFY2(std::abs(after.msv - 2.5) <= 0.3, formatCameraMeasurement(after).c_str());
        QVERIFY2(std::abs(after.u - 128) <= 2 * o.chromaTolerance && std::abs(after.v - 128) <= 2 * o.chromaTolerance,
                 formatCameraMeasurement(after).c_str());

        // Revert: the settings from before the run are back in the camera.
        QVERIFY(!calibration.revert());
        const CameraSettings startSettings = simulatedStartSettings(start);
        CameraFeature fe;
        QVERIFY(!cam.readFeature(CameraFeatureId::Exposure, fe));
        QCOMPARE(fe.value, startSettings.exposure);
        QVERIFY(!cam.readFeature(CameraFeatureId::WhiteBalanceRed, fe));
        QCOMPARE(fe.value, startSettings.whiteBalanceRed);
    }

    // Dark start, exposure capped low and gain capped: the image cannot get bright enough.
    void featureAtItsLimitIsReported()
    {
        SimulatedCamera cam(cameraOptions(SimulatedStart::Dark));
        QVERIFY(!cam.open());
        CameraAutoOptions o;
        o.exposureMax = 80;
        o.gainMax = 100;
        int lines = 0;
        const CameraAutoResult r = runCameraAutoCalibration(cam, o, ringMask(), [&](const CameraAutoIteration&) { ++lines; });
        QCOMPARE(int(r.state), int(CameraAutoState::Failed));
        QVERIFY(!r.error);
        QVERIFY2(r.reason.find("exposure and gain at their upper limits") != std::string::npos, r.reason.c_str());
        QVERIFY2(r.reason.find("too dark") != std::string::npos, r.reason.c_str());
        QVERIFY(r.iterations < o.maxIterations);  // gave up on the limit, not on the count
        QCOMPARE(lines, r.iterations);
        CameraFeature fe;
        QVERIFY(!cam.readFeature(CameraFeatureId::Exposure, fe));
        QVERIFY(fe.value <= 80);
        QVERIFY(!cam.readFeature(CameraFeatureId::Gain, fe));
        QVERIFY(fe.value <= 100);
    }

    // Counting the dark housing too (no mask) drives the exposure up until the white card
    // clips: clipped white must not pass as neutral (it did: "converged" with V/R still at 780).
    void clippedWhiteIsNeverNeutral()
    {
        SimulatedCameraOptions so;
        so.start = SimulatedStart::Tinted;
        so.poses = 2;
        SimulatedCamera cam(so);
        QVERIFY(!cam.open());
        const CameraAutoOptions o;
        const CameraAutoResult r = runCameraAutoCalibration(cam, o, cv::Mat());
        const cv::Vec3d w = r.last.measured.white;
        if (r.state == CameraAutoState::Converged)
            QVERIFY2(std::max({w[0], w[1], w[2]}) < o.whiteClip, formatCameraMeasurement(r.last.measured).c_str());
        else
            QVERIFY2(r.reason.find("the white region clips") != std::string::npos, r.reason.c_str());
    }

    void iterationCapIsReported()
    {
        SimulatedCamera cam(cameraOptions(SimulatedStart::Dark));
        QVERIFY(!cam.open());
        CameraAutoOptions o;
        o.maxIterations = 2;
        const CameraAutoResult r = runCameraAutoCalibration(cam, o, ringMask());
        QCOMPARE(int(r.state), int(CameraAutoState::Failed));
        QVERIFY2(r.reason.find("no convergence after 2 iterations") != std::string::npos, r.reason.c_str());
    }

    void unplugEndsTheRunWithTheCameraError()
    {
        SimulatedCamera cam(cameraOptions(SimulatedStart::Dark));
        QVERIFY(!cam.open());
        CameraAutoCalibration calibration(cam, CameraAutoOptions{}, ringMask());
        QVERIFY(!calibration.begin());
        CameraAutoIteration it;
        QVERIFY(!calibration.step(it));
        cam.simulateUnplug();
        const auto err = calibration.step(it);
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::Unplugged);
        QCOMPARE(int(calibration.state()), int(CameraAutoState::Failed));
    }
};

QTEST_GUILESS_MAIN(CameraAutoTest)
#include "calib_camera_auto_test.moc"
