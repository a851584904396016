// The camera panel on the simulated camera, driven with real key and mouse events: rows with
// the camera's own ranges and only the features it has, a typed value written and read back,
// a camera that holds another value shows the mismatch, the automatic calibration started from
// a tinted start converges and reverts, and "all auto off" turns the camera's auto modes off.
#include "calib/camera/SimulatedCamera.h"
#include "core/Config.h"
#include "core/Geometry.h"
#include "widgets/CameraPanel.h"

#include <QCheckBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QtTest>

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
        QTest::mouseClick(panel.allAutoOffButton(), Qt::LeftButton);
        QVERIFY(!cam.autoExposure);
        QVERIFY(!panel.autoBox(CameraFeatureId::Exposure)->isChecked());
        QVERIFY2(panel.statusText().contains("1 automatic mode"), qPrintable(panel.statusText()));

        typeInto(panel.spinBox(CameraFeatureId::Exposure), 405);
        QVERIFY2(panel.statusText().contains("exposure is 400, asked for 405"), qPrintable(panel.statusText()));
        QCOMPARE(panel.spinBox(CameraFeatureId::Exposure)->value(), 400);  // shows what the camera holds

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
