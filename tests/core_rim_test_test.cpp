// validation.rim_test (core/RimTest.h): a far ball cut by the mirror rim is judged instead of
// refused, while the rim's look-alikes (a robot's marker on its dark body, a line along the rim)
// are still refused there.
#include "DrawnCandidate.h"
#include "RimDistance.h"
#include "core/FrameColour.h"
#include "core/RimTest.h"
#include "core/Validation.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {

constexpr double kSquash = 0.6;      // a spherical mirror's far ring (optics matrix: 0.58-0.61)
constexpr double kAngle = 250.0;     // degrees; down-left, where the matrix's rim balls lie
inline const cv::Scalar kBlue(200, 90, 40);

Config rimConfig(bool rimTest)
{
    Config c;
    // The default ball model's ball is ~3 px at 240 px; at 200 px it is ~4.5 px, the size of the
    // optics matrix's rim balls.
    c.geometry.outerRadius = 200;
    c.ball.squashC0 = kSquash;
    c.validation.rimTest = rimTest;
    return c;
}

// The squashed ball (short axis towards the mirror centre); returns its centre.
cv::Point drawFarBall(cv::Mat& frame, const Config& c, double distance)
{
    const cv::Point2d q = pointAt(c, distance, kAngle);
    const cv::Point p(int(std::lround(q.x)), int(std::lround(q.y)));
    const double r = expectedRadius(c, distance);
    const cv::Size2f axes(float(2.0 * r * std::sqrt(kSquash)), float(2.0 * r / std::sqrt(kSquash)));
    // RotatedRect: width along the angle; pointAt's angle runs counter-clockwise with y up.
    cv::ellipse(frame, cv::RotatedRect(q, axes, float(-kAngle)), kOrange, cv::FILLED);
    return p;
}

BallCandidate validate(const Config& c, const cv::Mat& frame, cv::Point p) { return validateAt(c, frame, p); }

// A 200 x 200 image with the mirror centre in the middle: the arc 85 px below it runs along x.
GeometryOptions testGeometry()
{
    GeometryOptions g;
    g.imageWidth = 200;
    g.imageHeight = 200;
    g.centerX = 100;
    g.centerY = 100;
    g.innerRadius = 10;
    g.outerRadius = 90;
    return g;
}

}  // namespace

class RimTestTest : public QObject {
    Q_OBJECT
private slots:
    void farBallCutByTheRimIsJudged_data()
    {
        QTest::addColumn<double>("overhang");
        QTest::newRow("just past the margin") << 0.5;
        QTest::newRow("a third of it outside") << 2.5;
    }
    void farBallCutByTheRimIsJudged()
    {
        QFETCH(double, overhang);
        const Config on = rimConfig(true);
        const double d = distanceOverhanging(on, overhang);
        cv::Mat frame = greenField(on);
        const cv::Point p = drawFarBall(frame, on, d);
        const BallCandidate judged = validate(on, frame, p);
        QVERIFY2(judged.rejected == RejectReason::None, qPrintable(verdict(judged)));
        // The earlier rule refuses it for reaching past the rim.
        const BallCandidate refused = validate(rimConfig(false), frame, p);
        QCOMPARE(refused.rejected, RejectReason::OutsideArea);
    }

    // Too far past the rim: most of the circle is outside the mirror, nothing to judge.
    void circleMostlyOutsideIsRefused()
    {
        const Config on = rimConfig(true);
        const double d = distanceOverhanging(on, on.validation.rimMaxOverhangPx + 1.0);
        cv::Mat frame = greenField(on);
        const cv::Point p = drawFarBall(frame, on, d);
        QCOMPARE(validate(on, frame, p).rejected, RejectReason::OutsideArea);
    }

    // A robot's marker seen at the horizon: an upright rectangle, narrower than the ball the model
    // expects there, running out to the rim, on the robot's dark body.
    void markerAtTheRimIsRefused()
    {
        const Config on = rimConfig(true);
        const double d = distanceOverhanging(on, 1.5);
        const double r = expectedRadius(on, d);
        cv::Mat frame = greenField(on);
        const cv::Point2d q = pointAt(on, d, kAngle);
        const double width = 0.6 * rimExpectedWidthPx(r, kSquash);
        // Along the radius from the body's inner edge out past the rim.
        const cv::Point2d body = pointAt(on, d - r, kAngle);
        cv::ellipse(frame, cv::RotatedRect(body, cv::Size2f(float(1.5 * r), float(width + 2)), float(-kAngle)), kBlack,
                    cv::FILLED);
        cv::ellipse(frame, cv::RotatedRect(pointAt(on, d + r, kAngle), cv::Size2f(float(3 * r), float(width)), float(-kAngle)),
                    kBlue, cv::FILLED);
        const cv::Point p(int(std::lround(q.x)), int(std::lround(q.y)));
        const BallCandidate c = validate(on, frame, p);
        QVERIFY2(c.rejected == RejectReason::OutsideArea, qPrintable(verdict(c)));
    }

    // A white line along the rim: its run along the arc goes on far past a ball's width.
    void lineAlongTheRimIsRefused()
    {
        const Config on = rimConfig(true);
        const double d = distanceOverhanging(on, 1.5);
        cv::Mat frame = greenField(on);
        const cv::Point centre(int(std::lround(on.geometry.centerX)), int(std::lround(on.geometry.centerY)));
        cv::ellipse(frame, centre, cv::Size(int(std::lround(d)), int(std::lround(d))), 0, -kAngle - 15, -kAngle + 15, kWhite, 4);
        const cv::Point2d q = pointAt(on, d, kAngle);
        const BallCandidate c = validate(on, frame, {int(std::lround(q.x)), int(std::lround(q.y))});
        QVERIFY2(c.rejected == RejectReason::OutsideArea, qPrintable(verdict(c)));
    }

    // The measures themselves, on a hand-made class image.
    void arcRunAndClosure()
    {
        const Geometry geometry(testGeometry(), cv::Mat());
        const ColourRoles roles = defaultColourRoles();
        cv::Mat classes(200, 200, CV_8UC1, cv::Scalar(int(ColorClass::Green)));
        // An orange blob 9 px wide along x at (100, 185): the arc there runs along x.
        cv::rectangle(classes, cv::Rect(96, 183, 9, 5), cv::Scalar(int(ColorClass::Orange)), cv::FILLED);
        const double run = rimArcRunPx(classes, geometry, roles, 100, 185, 30.0);
        QVERIFY2(std::abs(run - 9.0) <= 1.0, qPrintable(QString::number(run)));  // the 0.5 px steps
        // Its inward side (towards y = 100) is closed 2 px up: a circle of radius 2 fits it.
        const RimClosure fits = rimClosure(classes, geometry, roles, 100, 185, 2.0, 1.0, 1.0, 0.9);
        QVERIFY(fits.judged > 0);
        QCOMPARE(fits.closedPct(), 100.0);
        // A radius of 6 expects the border 6 px up: the carpet comes too early.
        QCOMPARE(rimClosure(classes, geometry, roles, 100, 185, 6.0, 1.0, 1.0, 0.9).closedPct(), 0.0);
    }

    // validation.rim_arc_carpet_px: a speck of carpet in a floor strip along the arc does not end
    // the run; carpet that goes on does.
    void arcRunEndsAtCarpetThatGoesOn()
    {
        const Geometry geometry(testGeometry(), cv::Mat());
        const ColourRoles roles = defaultColourRoles();
        cv::Mat classes(200, 200, CV_8UC1, cv::Scalar(int(ColorClass::Green)));
        cv::rectangle(classes, cv::Rect(60, 183, 81, 5), cv::Scalar(int(ColorClass::Unknown)), cv::FILLED);
        classes.at<std::uint8_t>(185, 106) = std::uint8_t(ColorClass::Green);
        const double atSpeck = rimArcRunPx(classes, geometry, roles, 100, 185, 40.0, 0.0);
        const double pastSpeck = rimArcRunPx(classes, geometry, roles, 100, 185, 40.0, 1.0);
        QVERIFY2(pastSpeck > atSpeck + 8.0, qPrintable(QString("%1 %2").arg(atSpeck).arg(pastSpeck)));
        classes.at<std::uint8_t>(185, 107) = std::uint8_t(ColorClass::Green);
        QCOMPARE(rimArcRunPx(classes, geometry, roles, 100, 185, 40.0, 1.0), atSpeck);
    }

    // validation.rim_arc_masked_mirrors: a ball half behind a rod is as wide as its open side
    // says; the rim past the ring (not a mask) still ends a way as before.
    void arcRunMirrorsAWayEndingAtAMask()
    {
        cv::Mat mask(200, 200, CV_8UC1, cv::Scalar(255));
        cv::rectangle(mask, cv::Rect(103, 150, 4, 50), cv::Scalar(0), cv::FILLED);  // a rod across the arc
        const Geometry geometry(testGeometry(), mask);
        QVERIFY(geometry.maskedInRing().at<std::uint8_t>(185, 104) != 0);
        const ColourRoles roles = defaultColourRoles();
        cv::Mat classes(200, 200, CV_8UC1, cv::Scalar(int(ColorClass::Green)));
        // The 9 px orange blob of arcRunAndClosure, its +x side from x = 103 on behind the rod.
        cv::rectangle(classes, cv::Rect(96, 183, 9, 5), cv::Scalar(int(ColorClass::Orange)), cv::FILLED);
        const double cut = rimArcRunPx(classes, geometry, roles, 100, 185, 30.0, 0.0, false);
        const double mirrored = rimArcRunPx(classes, geometry, roles, 100, 185, 30.0, 0.0, true);
        QVERIFY2(std::abs(cut - 7.0) <= 1.0, qPrintable(QString::number(cut)));
        QVERIFY2(std::abs(mirrored - 9.0) <= 1.0, qPrintable(QString::number(mirrored)));
        QCOMPARE(rimWidestArcRunPx(classes, geometry, roles, 100, 185, 30.0, 0.0, 0.0, true), mirrored);
        // Without a mask both settings read the same arc.
        const Geometry open(testGeometry(), cv::Mat());
        QCOMPARE(rimArcRunPx(classes, open, roles, 100, 185, 30.0, 0.0, true),
                 rimArcRunPx(classes, open, roles, 100, 185, 30.0, 0.0, false));
    }

    // validation.rim_arc_offset_px: a centre found off the ball's widest chord still finds it.
    void widestArcRunReachesTheWidestChord()
    {
        const Geometry geometry(testGeometry(), cv::Mat());
        const ColourRoles roles = defaultColourRoles();
        cv::Mat classes(200, 200, CV_8UC1, cv::Scalar(int(ColorClass::Green)));
        // A squashed ball at (100, 185): 13 px along the arc (x), 7 px towards the centre (y).
        cv::ellipse(classes, cv::Point(100, 185), cv::Size(6, 3), 0, 0, 360, cv::Scalar(int(ColorClass::Orange)),
                    cv::FILLED);
        const double widestChord = rimArcRunPx(classes, geometry, roles, 100, 185, 30.0);
        // The candidate 2 px outwards of the ball's centre: its own arc cuts the ball short.
        const double offChord = rimArcRunPx(classes, geometry, roles, 100, 187, 30.0);
        QVERIFY2(offChord < widestChord, qPrintable(QString("%1 %2").arg(offChord).arg(widestChord)));
        QCOMPARE(rimWidestArcRunPx(classes, geometry, roles, 100, 187, 30.0, 0.0, 0.0), offChord);
        const double oneOff = rimArcRunPx(classes, geometry, roles, 100, 186, 30.0);
        QCOMPARE(rimWidestArcRunPx(classes, geometry, roles, 100, 187, 30.0, 0.0, 1.0), oneOff);
        QVERIFY(oneOff > offChord);
        QCOMPARE(rimWidestArcRunPx(classes, geometry, roles, 100, 187, 30.0, 0.0, 2.0), widestChord);
    }

    // validation.rim_skip_inner_field: a green panel inside the ball no longer stands for the
    // carpet on its inward side.
    void closureSkipsAGreenPanelInside()
    {
        const Geometry geometry(testGeometry(), cv::Mat());
        const ColourRoles roles = defaultColourRoles();
        cv::Mat classes(200, 200, CV_8UC1, cv::Scalar(int(ColorClass::Green)));
        // A ball 4 px in radius at (100, 185) whose border towards the centre is at y = 181,
        // with a green panel 2 px inwards of its centre.
        cv::rectangle(classes, cv::Rect(92, 181, 17, 9), cv::Scalar(int(ColorClass::Orange)), cv::FILLED);
        cv::line(classes, {97, 183}, {103, 183}, cv::Scalar(int(ColorClass::Green)));
        const RimClosure first = rimClosure(classes, geometry, roles, 100, 185, 4.0, 1.0, 1.0, 0.9, false);
        const RimClosure skipping = rimClosure(classes, geometry, roles, 100, 185, 4.0, 1.0, 1.0, 0.9, true);
        QVERIFY(first.judged > 0);
        QCOMPARE(first.closedPct(), 0.0);
        QCOMPARE(skipping.closedPct(), 100.0);
    }
};

QTEST_APPLESS_MAIN(RimTestTest)
#include "core_rim_test_test.moc"
