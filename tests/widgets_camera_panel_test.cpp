// The camera panel on the simulated camera, driven with real key and mouse events: rows with
// the camera's own ranges and only the features it has, a typed value written and read back,
// a camera that holds another value shows the mismatch, the automatic calibration started from
// a tinted start converges and reverts, and "all auto off" turns the camera's auto modes off
// and says so; a live frame shows its intensity histogram and MSV; the convergence plots get
// one point per iteration of a run from a dark start, cleared when the next run starts.
#include "calib/camera/SimulatedCamera.h"
#include "core/Config.h"
#include "core/Geometry.h"
#include "calib/camera/MeanSampleValue.h"
#include "widgets/CalibrationPlot.h"
#include "widgets/CameraPanel.h"
#include "widgets/IntensityHistogramView.h"

#include <QLineSeries>

#include <QCheckBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QtTest>

#include <opencv2/imgproc.hpp>

#include <numeric>

using namespace omnitune;

namespace {

SimulatedCameraOptions quickCamera(SimulatedStart start = SimulatedStart::Good)
{
    SimulatedCameraOptions o;
    o.start = start;
    o.poses = 2;
    return o;
}

// A camera whose exposure register takes steps of 10 and that has an automatic exposure, like
// many real ones: what it holds differs from what was asked.
class SteppedCamera : public SimulatedCamera {
public:
    using SimulatedCamera::SimulatedCamera;
    std::vector<CameraFeature> features() override
    {
        auto f = SimulatedCamera::features();
        for (auto& x : f)
            if (x.id == CameraFeatureId::Exposure) x.autoCapable = true, x.autoOn = autoExposure;
        return f;
    }
    bool autoExposure = true;

protected:
    std::optional<CameraError> writeFeature(CameraFeatureId id, int value) override
    {
        if (id == CameraFeatureId::Exposure) autoExposure = false, value = value / 10 * 10;
        return SimulatedCamera::writeFeature(id, value);
    }
    std::optional<CameraError> writeAuto(CameraFeatureId id, bool on) override
    {
        if (id == CameraFeatureId::Exposure) autoExposure = on;
        return std::nullopt;
    }
};

void typeInto(QSpinBox* spin, int value)
{
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QString::number(value));
    QTest::keyClick(spin, Qt::Key_Enter);
}

}  // namespace

class CameraPanelTest : public QObject {
    Q_OBJECT

private slots:
    void rowsFollowTheCamera()
    {
        SimulatedCamera cam(quickCamera());
        QVERIFY(!cam.open());
        CameraPanel panel;
        panel.setCamera(&cam);
        panel.show();
        QVERIFY(panel.spinBox(CameraFeatureId::Exposure));
        QCOMPARE(panel.spinBox(CameraFeatureId::Exposure)->maximum(), 4095);
        QCOMPARE(panel.slider(CameraFeatureId::Gain)->maximum(), 1023);
        QCOMPARE(panel.spinBox(CameraFeatureId::Exposure)->value(), 300);
        QVERIFY(!panel.spinBox(CameraFeatureId::Gamma));  // the simulated camera has none
        QVERIFY(!panel.autoBox(CameraFeatureId::Exposure)->isEnabled());
        QVERIFY(!panel.revertButton()->isEnabled());

        panel.setCamera(nullptr);
        QVERIFY(!panel.spinBox(CameraFeatureId::Exposure));
        QVERIFY(!panel.startButton()->isEnabled());
    }

    void typedValueIsWrittenAndReadBack()
    {
        SimulatedCamera cam(quickCamera());
        QVERIFY(!cam.open());
        CameraPanel panel;
        panel.setCamera(&cam);
        panel.show();
        typeInto(panel.spinBox(CameraFeatureId::Gain), 350);
        CameraFeature f;
        QVERIFY(!cam.readFeature(CameraFeatureId::Gain, f));
        QCOMPARE(f.value, 350);
        QCOMPARE(panel.slider(CameraFeatureId::Gain)->value(), 350);

        // The slider writes too.
        QSlider* s = panel.slider(CameraFeatureId::Brightness);
        s->setFocus();
        QTest::keyClick(s, Qt::Key_PageUp);
        QVERIFY(!cam.readFeature(CameraFeatureId::Brightness, f));
        QCOMPARE(f.value, s->value());
        QVERIFY(f.value != 100);
    }

    void mismatchIsShownAndAutoOffWorks()
    {
        SteppedCamera cam(quickCamera());
        QVERIFY(!cam.open());
        CameraPanel panel;
        panel.setCamera(&cam);
        panel.show();
        QVERIFY(panel.autoBox(CameraFeatureId::Exposure)->isEnabled());
        QVERIFY(panel.autoBox(CameraFeatureId::Exposure)->isChecked());
        QVERIFY2(panel.autoStateText().contains("ON: exposure"), qPrintable(panel.autoStateText()));
        QTest::mouseClick(panel.allAutoOffButton(), Qt::LeftButton);
        QVERIFY2(panel.autoStateText().contains("all off"), qPrintable(panel.autoStateText()));
        QVERIFY(!cam.autoExposure);
        QVERIFY(!panel.autoBox(CameraFeatureId::Exposure)->isChecked());
        QVERIFY2(panel.statusText().contains("1 automatic mode"), qPrintable(panel.statusText()));

        typeInto(panel.spinBox(CameraFeatureId::Exposure), 405);
        QVERIFY2(panel.statusText().contains("exposure is 400, asked for 405"), qPrintable(panel.statusText()));
        QCOMPARE(panel.spinBox(CameraFeatureId::Exposure)->value(), 400);  // shows what the camera holds
        QCOMPARE(panel.mismatchText(CameraFeatureId::Exposure), QStringLiteral("asked for 405"));  // beside the row
        typeInto(panel.spinBox(CameraFeatureId::Exposure), 510);
        QCOMPARE(panel.spinBox(CameraFeatureId::Exposure)->value(), 510);
        QVERIFY(panel.mismatchText(CameraFeatureId::Exposure).isEmpty());  // held as asked: the note goes

        QTest::mouseClick(panel.autoBox(CameraFeatureId::Exposure), Qt::LeftButton);
        QVERIFY(cam.autoExposure);
    }

    void calibrationConvergesAndReverts()
    {
        SimulatedCameraOptions o;  // the whole tour, as omnitune-camera runs it
        o.start = SimulatedStart::Tinted;
        SimulatedCamera cam(o);
        QVERIFY(!cam.open());
        CameraPanel panel;
        const Config config;  // the MSV counts the ring the detector uses, as in the window
        panel.setCamera(&cam, config.cameraAuto, Geometry(config.geometry, config.mask).usedMask());
        panel.show();
        QSignalSpy iterations(&panel, &CameraPanel::calibrationIteration);
        QSignalSpy finished(&panel, &CameraPanel::calibrationFinished);
        QTest::mouseClick(panel.startButton(), Qt::LeftButton);
        QVERIFY(panel.stopButton()->isEnabled());
        QVERIFY(!panel.startButton()->isEnabled());
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        QVERIFY(panel.statusText().startsWith("converged: msv="));
        QCOMPARE(iterations.count(), panel.statusText().section("iterations=", 1).toInt());
        const int wbRed = panel.spinBox(CameraFeatureId::WhiteBalanceRed)->value();
        QVERIFY2(wbRed < 700, qPrintable(QString::number(wbRed)));  // the red cast was taken out
        CameraFeature f;
        QVERIFY(!cam.readFeature(CameraFeatureId::WhiteBalanceRed, f));
        QCOMPARE(f.value, wbRed);

        QVERIFY(panel.revertButton()->isEnabled());
        QTest::mouseClick(panel.revertButton(), Qt::LeftButton);
        QVERIFY(!cam.readFeature(CameraFeatureId::WhiteBalanceRed, f));
        QCOMPARE(f.value, 900);
        QCOMPARE(panel.spinBox(CameraFeatureId::WhiteBalanceRed)->value(), 900);
    }

    void liveFrameShowsHistogramAndMsv()
    {
        SimulatedCamera cam(quickCamera());
        QVERIFY(!cam.open());
        QVERIFY(!cam.start());
        const Config config;
        const cv::Mat mask = Geometry(config.geometry, config.mask).usedMask();
        CameraPanel panel;
        panel.setCamera(&cam, config.cameraAuto, mask);
        panel.setHistogramInterval(0);  // every frame
        Frame f;
        QVERIFY(!cam.grab(f));
        panel.showFrame(f.image);
        QVERIFY(panel.histogramView()->histogram().empty());  // a hidden panel computes nothing
        panel.show();
        panel.showFrame(f.image);
        const std::vector<double> h = panel.histogramView()->histogram();
        QCOMPARE(int(h.size()), config.cameraAuto.histogramRegions);
        QCOMPARE(std::accumulate(h.begin(), h.end(), 0.0), double(cv::countNonZero(mask)));  // the used pixels only
        CameraMeasurement m;
        QVERIFY(!measureCameraFrame(f.image, mask, config.cameraAuto, m));
        QCOMPARE(panel.histogramView()->msv(), m.msv);
        QVERIFY2(panel.msvText().startsWith(QStringLiteral("MSV %1 (target 2.50").arg(m.msv, 0, 'f', 2)),
                 qPrintable(panel.msvText()));

        // A darker frame moves the histogram to the left.
        panel.showFrame(f.image / 4);
        QVERIFY2(panel.histogramView()->msv() < m.msv - 0.5, qPrintable(panel.msvText()));
        QVERIFY(panel.histogramView()->histogram().front() > h.front());

        // A geometry for another size: the whole frame is counted, and the panel says so.
        cv::Mat small;
        cv::resize(f.image, small, {480, 400});
        panel.showFrame(small);
        const std::vector<double>& all = panel.histogramView()->histogram();
        QCOMPARE(std::accumulate(all.begin(), all.end(), 0.0), 480.0 * 400.0);
        QVERIFY2(panel.msvText().contains("whole frame"), qPrintable(panel.msvText()));
    }

    void plotsFollowTheCalibration()
    {
        SimulatedCamera cam(quickCamera(SimulatedStart::Dark));
        QVERIFY(!cam.open());
        CameraPanel panel;
        const Config config;
        panel.setCamera(&cam, config.cameraAuto, Geometry(config.geometry, config.mask).usedMask());
        panel.show();
        QSignalSpy iterations(&panel, &CameraPanel::calibrationIteration);
        QSignalSpy finished(&panel, &CameraPanel::calibrationFinished);
        QTest::mouseClick(panel.startButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        const QtCharts::QLineSeries* msv = panel.plot()->msvSeries();
        QCOMPARE(msv->count(), iterations.count());
        QVERIFY(iterations.count() >= 3);  // a dark start takes a few
        QCOMPARE(panel.plot()->blackSeries()->count(), iterations.count());
        QCOMPARE(panel.plot()->uSeries()->count(), iterations.count());
        QCOMPARE(panel.plot()->vSeries()->count(), iterations.count());
        QVERIFY2(msv->at(0).y() < 2.0, qPrintable(QString::number(msv->at(0).y())));  // it started dark
        const QPointF last = msv->at(msv->count() - 1);
        QCOMPARE(int(last.x()), iterations.count());
        QVERIFY2(std::abs(last.y() - config.cameraAuto.msvTarget) <= config.cameraAuto.msvTolerance,
                 qPrintable(QString::number(last.y())));
        const double lastV = panel.plot()->vSeries()->at(iterations.count() - 1).y();  // V - target
        QVERIFY2(std::abs(lastV) <= config.cameraAuto.chromaTolerance, qPrintable(QString::number(lastV)));

        if (qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR")) {  // to look at the histogram and the plots
            panel.resize(420, 900);
            Frame f;
            QVERIFY(!cam.grab(f));
            panel.showFrame(f.image);
            panel.grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/camera-panel.png");
        }

        // The next run starts from an empty plot and shows only its own iterations.
        const int firstRun = iterations.count();
        QTest::mouseClick(panel.startButton(), Qt::LeftButton);
        QCOMPARE(msv->count(), 0);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
        QCOMPARE(msv->count(), iterations.count() - firstRun);
        QCOMPARE(msv->at(0).x(), 1.0);
    }

    void stopHaltsTheCalibration()
    {
        SimulatedCamera cam(quickCamera(SimulatedStart::Dark));
        QVERIFY(!cam.open());
        CameraPanel panel;
        panel.setCamera(&cam);
        panel.show();
        QSignalSpy iterations(&panel, &CameraPanel::calibrationIteration);
        QTest::mouseClick(panel.startButton(), Qt::LeftButton);
        QTRY_VERIFY(iterations.count() >= 1);
        QTest::mouseClick(panel.stopButton(), Qt::LeftButton);
        const int n = iterations.count();
        QTest::qWait(0);
        QCoreApplication::processEvents();
        QCOMPARE(iterations.count(), n);
        QVERIFY(panel.statusText().contains("stopped"));
        QVERIFY(panel.startButton()->isEnabled());
    }
};

QTEST_MAIN(CameraPanelTest)
#include "widgets_camera_panel_test.moc"
