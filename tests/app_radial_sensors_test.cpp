// Issue 11, radial sensors on the panes: in editing mode (R) the ends of a ray drag the
// sensors' inner and outer radius, its middle turns every ray (sensors.angle_offset), each
// drag one undo step; a click selects a ray and the strip under the panes shows the colour
// classes the robot would read along it. The ray is turned onto the demo's ball (frame 0),
// so the strip must show the ball's class where the ball is.
#include "app/MainWindow.h"
#include "core/ColorClass.h"
#include "widgets/ConfigDocument.h"
#include "widgets/ImageView.h"
#include "widgets/PaneEditors.h"
#include "widgets/PipelineRunner.h"
#include "widgets/PipelineView.h"
#include "widgets/RadialSensorEditor.h"
#include "widgets/RayStrip.h"
#include "WindowTestSupport.h"

#include <QDoubleSpinBox>
#include <QtTest>

#include <cmath>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

// Waits until the window shows frame 0 processed with the config's sensors.
bool waitForSensors(MainWindow& window, const RadialSensorOptions& s)
{
    QSignalSpy spy(&window, &MainWindow::runShown);
    for (int i = 0; i < 50; ++i) {
        const auto run = window.lastRun();
        if (!window.isProcessing() && run && run->result.ok() && run->config.sensors.angleOffsetDeg == s.angleOffsetDeg &&
            run->config.sensors.outerRadius == s.outerRadius)
            return true;
        spy.wait(200);
    }
    return false;
}

}  // namespace

class RadialSensorsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        startWindowTests();
        QVERIFY(dir_.isValid());
        QVERIFY(copyDemo(dir_.path()));
    }

    void init()
    {
        QVERIFY(openWindow(window_, dir_.path(), Shown::Active));
        QTest::keyClick(window_.get(), Qt::Key_R);
        QVERIFY(editor()->isEditing());
        QVERIFY(strip()->isVisible());
    }

    void cleanup()
    {
        if (window_) window_->document()->discardChanges();
        window_.reset();
    }

    void dragTheEndsAndTurnTheRays()
    {
        ConfigDocument* doc = window_->document();
        const Config before = doc->config();
        const RadialSensorOptions& s = doc->config().sensors;
        QCOMPARE(s.angleOffsetDeg, 0.0);  // ray 0 points along +x
        ImageView* pane = window_->pipelineView()->pane(PipelineView::Segmented);
        const QPointF c(before.geometry.centerX, before.geometry.centerY);
        const auto radius = [&](QPointF p) { return std::hypot(p.x() - c.x(), p.y() - c.y()); };
        const auto degrees = [&](QPointF p) { return std::atan2(-(p.y() - c.y()), p.x() - c.x()) * 180.0 / M_PI; };
        const int steps = doc->undoStack()->count();
        // Where the drags end, as the pane reports them (whole widget px): the radii follow to
        // within the half-pixel snap.
        QPointF end = dragOnPane(pane, c + QPointF(s.outerRadius, 0), c + QPointF(s.outerRadius - 30, 0)).second;
        QVERIFY2(std::abs(doc->config().sensors.outerRadius - radius(end)) <= 0.25,
                 qPrintable(QString("%1 vs %2").arg(doc->config().sensors.outerRadius).arg(radius(end))));
        QVERIFY(doc->config().sensors.outerRadius < before.sensors.outerRadius - 25);
        end = dragOnPane(pane, c + QPointF(s.innerRadius, 0), c + QPointF(s.innerRadius + 20, 0)).second;
        QVERIFY2(std::abs(doc->config().sensors.innerRadius - radius(end)) <= 0.25,
                 qPrintable(QString("%1 vs %2").arg(doc->config().sensors.innerRadius).arg(radius(end))));
        QVERIFY(doc->config().sensors.innerRadius > before.sensors.innerRadius + 15);
        QCOMPARE(doc->undoStack()->count(), steps + 2);

        // Grabbed in the middle and moved about 5 degrees counter-clockwise, every ray turns with it.
        const double mid = (doc->config().sensors.innerRadius + doc->config().sensors.outerRadius) / 2;
        const double a = 5.0 * M_PI / 180.0;
        const auto [from, to] = dragOnPane(pane, c + QPointF(mid, 0), c + mid * QPointF(std::cos(a), -std::sin(a)));
        const double turned = doc->config().sensors.angleOffsetDeg;
        QVERIFY2(std::abs(turned - (degrees(to) - degrees(from))) <= 0.06,
                 qPrintable(QString("%1 vs %2").arg(turned).arg(degrees(to) - degrees(from))));
        QVERIFY(turned > 3.0 && turned < 7.0);
        QCOMPARE(doc->undoStack()->count(), steps + 3);
        QCOMPARE(doc->config().sensors.count, before.sensors.count);

        // A press beyond the rays' ends does nothing.
        const double beyond = doc->config().sensors.outerRadius + 40;
        dragOnPane(pane, c + QPointF(-beyond, 0), c + QPointF(-beyond, 30));
        QCOMPARE(doc->undoStack()->count(), steps + 3);

        for (int i = 0; i < 3; ++i) doc->undoStack()->undo();
        QCOMPARE(doc->config().sensors.outerRadius, before.sensors.outerRadius);
        QCOMPARE(doc->config().sensors.innerRadius, before.sensors.innerRadius);
        QCOMPARE(doc->config().sensors.angleOffsetDeg, 0.0);
    }

    void aSelectedRayShowsItsClassesUnderThePanes()
    {
        ConfigDocument* doc = window_->document();
        const Config& c = doc->config();
        // The truth of frame 0: the ball at (320, 65). Turn ray 0 onto it in the threshold panel.
        const QPointF ball(320, 65), centre(c.geometry.centerX, c.geometry.centerY);
        const double ballR = std::hypot(ball.x() - centre.x(), ball.y() - centre.y());
        QVERIFY(ballR > c.sensors.innerRadius && ballR < c.sensors.outerRadius);
        double deg = std::atan2(-(ball.y() - centre.y()), ball.x() - centre.x()) * 180.0 / M_PI;
        if (deg < 0) deg += 360.0;
        auto* offset = window_->findChild<QDoubleSpinBox*>(QStringLiteral("sensors.angle_offset"));
        QVERIFY2(offset, "the threshold panel has no editor for sensors.angle_offset");
        offset->setValue(deg);
        QVERIFY2(std::abs(c.sensors.angleOffsetDeg - deg) < 0.6, qPrintable(QString::number(c.sensors.angleOffsetDeg)));
        deg = c.sensors.angleOffsetDeg;  // as the panel rounded it
        QVERIFY(waitForSensors(*window_, c.sensors));
        const cv::Mat& classes = window_->lastRun()->result.classes;
        const auto ballClass = ColorClass(classes.at<std::uint8_t>(int(ball.y()), int(ball.x())));
        QVERIFY(ballClass != ColorClass::Green && ballClass != ColorClass::Unknown);

        QCOMPARE(strip()->ray(), -1);
        ImageView* pane = window_->pipelineView()->pane(PipelineView::Acquired);
        const double a = deg * M_PI / 180.0;
        const double mid = (c.sensors.innerRadius + ballR) / 2;  // on ray 0, short of the ball
        const int steps = doc->undoStack()->count();
        const QPoint at = pane->toWidget(centre + mid * QPointF(std::cos(a), -std::sin(a))).toPoint();
        QTest::mouseClick(pane, Qt::LeftButton, {}, at);
        QCOMPARE(doc->undoStack()->count(), steps);  // a click selects, it changes nothing
        QCOMPARE(editor()->selectedRay(), 0);
        QCOMPARE(strip()->ray(), 0);
        bool seen = false;
        for (const ClassRun& r : strip()->runs())
            if (r.colorClass == ballClass && r.startRadius <= ballR + 1 && r.endRadius >= ballR - 1) seen = true;
        QVERIFY2(seen, "the strip shows no run of the ball's class at the ball's radius");
        if (qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR"))  // to look at the rays and the strip
            window_->grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/radial-sensors.png");
        bool green = false;
        for (const ClassRun& r : strip()->runs()) green |= r.colorClass == ColorClass::Green;
        QVERIFY(green);  // the carpet on the way

        // R again hides the strip and gives the left button back.
        QTest::keyClick(window_.get(), Qt::Key_R);
        QVERIFY(!editor()->isEditing());
        QVERIFY(!strip()->isVisible());
        QCOMPARE(window_->pipelineView()->paneEditor(), nullptr);
    }

    void oneEditorHoldsTheLeftButton()
    {
        QTest::keyClick(window_.get(), Qt::Key_M);  // the mask editor takes over
        QVERIFY(!editor()->isEditing());
        QVERIFY(!strip()->isVisible());
        QTest::keyClick(window_.get(), Qt::Key_R);
        QVERIFY(editor()->isEditing());
        QTest::keyClick(window_.get(), Qt::Key_Escape);
        QVERIFY(!editor()->isEditing());
    }

private:
    RadialSensorEditor* editor() const { return window_->paneEditors()->sensors(); }
    RayStrip* strip() const { return window_->findChild<RayStrip*>(); }

    QTemporaryDir dir_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(RadialSensorsTest)
#include "app_radial_sensors_test.moc"
