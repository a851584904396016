// validation.run_on_chroma_step (issue 9): in dim light a coloured ball and a grey line both
// leave every colour class, so the run-on test, which follows the centre's class, followed the
// line out of a ball touching it and rejected the ball as a line corner. With the step an
// unclassified pixel that is greyer than the centre by more than the step (chroma, max - min of
// B, G, R) and no darker is line paint and ends the run; a grey line's own corner, or a
// coloured blob going on into its own shading, still runs on.
#include "DrawnCandidate.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;
Q_DECLARE_METATYPE(omnitune::RejectReason)
Q_DECLARE_METATYPE(cv::Scalar)

namespace {

constexpr double kDistance = 150;  // px from the robot centre
constexpr double kAngle = 30;      // degrees
const cv::Scalar kDimGrey(95, 95, 95);     // a line in a dim hall: no class
const cv::Scalar kDimOrange(25, 50, 75);   // an orange ball in the same light (V 75): no class either

// Unit vectors of the ball's radial direction and of the line's, across it.
cv::Point2d radial()
{
    return {std::cos(kAngle * M_PI / 180.0), std::sin(kAngle * M_PI / 180.0)};
}
cv::Point2d alongLine()
{
    return {-radial().y, radial().x};
}

// The dim orange ball of the expected radius centred on `p`, touching a dim line half its radius
// wide (a line is 12 cm, a ball 22 cm) on its far side: from the centre, rays towards the line
// meet grey within the run-on reach over about a fifth of the circle.
cv::Mat ballTouchingDimLine(const Config& c, cv::Point p)
{
    cv::Mat frame = greenField(c);
    const double r = expectedRadius(c, kDistance);
    const double w = std::max(3.0, r / 2.0);
    const cv::Point2d mid = cv::Point2d(p) + (r + w / 2.0 - 1.0) * radial();
    cv::line(frame, rounded(mid - 80.0 * alongLine()), rounded(mid + 80.0 * alongLine()), kDimGrey,
             int(std::lround(w)));
    cv::circle(frame, p, int(std::lround(r)), kDimOrange, cv::FILLED);
    return frame;
}

cv::Point centreAt(const Config& c)
{
    return rounded(pointAt(c, kDistance, kAngle));
}

}  // namespace

class ValidationRunOnChromaTest : public QObject {
    Q_OBJECT
private slots:
    // The premise: ball and line share the "no class" class, so the class alone cannot tell
    // the ball's border where it touches the line.
    void dimColoursAreUnclassified()
    {
        const Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = ballTouchingDimLine(c, p);
        const EdgeStages s(c, frame);
        const cv::Point q = rounded(cv::Point2d(p) + (expectedRadius(c, kDistance) + 2.0) * radial());
        QCOMPARE(int(s.classes.at<std::uint8_t>(p)), 0);
        QCOMPARE(int(s.classes.at<std::uint8_t>(q)), 0);
    }

    void ballTouchingADimLinePassesWithTheStep()
    {
        Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = ballTouchingDimLine(c, p);
        QVERIFY(c.validation.runOnChromaStep > 0.0);
        const BallCandidate on = validateAt(c, frame, p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
        // The colour step (run_on_colour_step) ends this run too: off, so the chroma step's own
        // effect shows.
        c.validation.runOnColourStep = 0.0;
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::None);
        c.validation.runOnChromaStep = 0.0;
        const BallCandidate off = validateAt(c, frame, p);
        QVERIFY2(off.rejected == RejectReason::RunsOn, qPrintable(verdict(off)));
        QVERIFY(off.scores.runOnPct > on.scores.runOnPct);
    }

    // A blob of the ball's size where two stripes meet still runs on: a dim grey line corner
    // (grey goes on in grey), and a coloured blob whose stripes are its own darker, greyer
    // shading (a leg in dim light): only paler paint that is no darker breaks a run.
    void cornersStillRunOn_data()
    {
        QTest::addColumn<cv::Scalar>("blob");
        QTest::addColumn<cv::Scalar>("stripes");
        QTest::newRow("grey line corner") << kDimGrey << kDimGrey;
        QTest::newRow("colour into darker shading") << cv::Scalar(110, 40, 20) << cv::Scalar(66, 44, 40);
    }
    void cornersStillRunOn()
    {
        QFETCH(cv::Scalar, blob);
        QFETCH(cv::Scalar, stripes);
        const Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = centreAt(c);
        const int r = int(std::lround(expectedRadius(c, kDistance)));
        cv::line(frame, p, p + cv::Point(60, 0), stripes, r);
        cv::line(frame, p, p + cv::Point(52, 30), stripes, r);
        cv::circle(frame, p, r, blob, cv::FILLED);
        const EdgeStages s(c, frame);
        QCOMPARE(int(s.classes.at<std::uint8_t>(p)), 0);
        QCOMPARE(int(s.classes.at<std::uint8_t>(p + cv::Point(2 * r, 0))), 0);
        const BallCandidate corner = validateAt(c, frame, p);
        QVERIFY2(corner.rejected == RejectReason::RunsOn, qPrintable(verdict(corner)));
    }
};

QTEST_GUILESS_MAIN(ValidationRunOnChromaTest)
#include "core_validation_run_on_chroma_test.moc"
