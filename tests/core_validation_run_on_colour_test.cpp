// validation.run_on_colour_step (issue 9): a ball at the carpet's edge lies against the grey hall
// floor beyond it. Both leave every colour class, so the run-on test, which follows the centre's
// class, followed the floor out of the ball and rejected the ball as a line corner; a grey floor
// has no hue to tell it by, and it is no greyer than a dark ball. With the step an unclassified
// pixel whose colour lies far from the centre's, and is no darker, ends the run; a blob going on
// in its own colour (a line corner in shading) or into a darker one (a leg into its shoe) still
// runs on.
#include "DrawnCandidate.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;
Q_DECLARE_METATYPE(cv::Scalar)

namespace {

constexpr double kDistance = 150;  // px from the robot centre
constexpr double kAngle = 30;      // degrees
const cv::Scalar kDarkBall(78, 72, 70);   // a dark, nearly grey ball: no class, no hue to speak of
const cv::Scalar kHallFloor(125, 122, 120);  // the hall floor beyond the carpet: no class either

cv::Point centreAt(const Config& c)
{
    return rounded(pointAt(c, kDistance, kAngle));
}

// A blob of the expected radius centred on `p` whose outer rim touches a floor that begins 0.85
// radii out and goes on outwards, as a ball at the carpet's edge is seen against the floor: a
// quarter of its rays meet the floor within the run-on reach, a sixth of its border is floor.
cv::Mat blobAgainstFloor(const Config& c, cv::Point p, const cv::Scalar& blob, const cv::Scalar& floor)
{
    cv::Mat frame = greenField(c);
    const double r = expectedRadius(c, kDistance);
    const cv::Point2d out = radialAt(kAngle);
    const cv::Point2d across(-out.y, out.x);
    const cv::Point2d a = cv::Point2d(p) + 0.85 * r * out;
    std::vector<cv::Point> floorPolygon = {rounded(a + 4 * r * across), rounded(a - 4 * r * across),
                                           rounded(a - 4 * r * across + 6 * r * out), rounded(a + 4 * r * across + 6 * r * out)};
    cv::fillConvexPoly(frame, floorPolygon, floor);
    cv::circle(frame, p, int(std::lround(r)), blob, cv::FILLED);
    return frame;
}

cv::Point onFloor(const Config& c, cv::Point p)
{
    return rounded(cv::Point2d(p) + 2.0 * expectedRadius(c, kDistance) * radialAt(kAngle));
}

}  // namespace

class ValidationRunOnColourTest : public QObject {
    Q_OBJECT
private slots:
    // The premise: ball and floor share the "no class" class, and neither the chroma step (the
    // floor is not greyer by 20) nor the hue step (the floor has no chroma) ends a run into it.
    void ballAndFloorAreUnclassified()
    {
        const Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = blobAgainstFloor(c, p, kDarkBall, kHallFloor);
        QCOMPARE(classAt(c, frame, p), 0);
        QCOMPARE(classAt(c, frame, onFloor(c, p)), 0);
        Config off = c;
        off.validation.runOnColourStep = 0.0;
        const BallCandidate without = validateAt(off, frame, p);
        QVERIFY2(without.rejected == RejectReason::RunsOn, qPrintable(verdict(without)));
    }

    void ballAgainstTheFloorPassesWithTheStep()
    {
        const Config c;
        QVERIFY(c.validation.runOnColourStep > 0.0);
        const cv::Point p = centreAt(c);
        const BallCandidate on = validateAt(c, blobAgainstFloor(c, p, kDarkBall, kHallFloor), p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
    }

    // The step is read from the config: one wider than the colours lie apart (47 + 50 + 50) keeps the run.
    void stepFromTheConfig()
    {
        Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = blobAgainstFloor(c, p, kDarkBall, kHallFloor);
        c.validation.runOnColourStep = 160.0;
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::RunsOn);
        c.validation.runOnColourStep = 130.0;
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::None);
    }

    // What still runs on: the floor's own colour a little darker at the blob (shading, 14 + 14 + 14
    // apart), as a line corner goes on in its own colour; and a darker colour however far apart (a
    // leg going on into its shoe).
    void ownColourAndDarkerStillRunOn_data()
    {
        QTest::addColumn<cv::Scalar>("blob");
        QTest::addColumn<cv::Scalar>("floor");
        QTest::newRow("own colour in shading") << kHallFloor - cv::Scalar(14, 14, 14) << kHallFloor;
        QTest::newRow("into a darker colour") << kHallFloor << kDarkBall;
    }
    void ownColourAndDarkerStillRunOn()
    {
        QFETCH(cv::Scalar, blob);
        QFETCH(cv::Scalar, floor);
        const Config c;
        const cv::Point p = centreAt(c);
        const BallCandidate candidate = validateAt(c, blobAgainstFloor(c, p, blob, floor), p);
        QVERIFY2(candidate.rejected == RejectReason::RunsOn, qPrintable(verdict(candidate)));
    }
};

QTEST_GUILESS_MAIN(ValidationRunOnColourTest)
#include "core_validation_run_on_colour_test.moc"
