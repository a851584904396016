// validation.run_on_hue_step (issue 9): in dim light a ball lying against a robot's marker band
// leaves every colour class, as the band does, so the run-on test, which follows the centre's
// class, followed the band out of the ball and rejected the ball as a line corner. With the step
// an unclassified pixel whose hue lies far from the centre's (both with some chroma) ends the run;
// a blob going on in its own hue, or grey pixels whose hue is noise, still run on.
#include "DrawnCandidate.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;
Q_DECLARE_METATYPE(cv::Scalar)

namespace {

constexpr double kDistance = 150;  // px from the robot centre
constexpr double kAngle = 30;      // degrees
const cv::Scalar kDimOrange(25, 50, 75);    // an orange ball in a dim hall (V 75): no class
const cv::Scalar kDimMagenta(60, 12, 65);   // a robot's magenta marker band in the same light: no class

cv::Point2d radial()
{
    return {std::cos(kAngle * M_PI / 180.0), std::sin(kAngle * M_PI / 180.0)};
}

cv::Point centreAt(const Config& c)
{
    return rounded(pointAt(c, kDistance, kAngle));
}

// A pixel on the band, two expected radii out from the blob's centre `p`.
cv::Point onBand(const Config& c, cv::Point p)
{
    return rounded(cv::Point2d(p) + 2.0 * expectedRadius(c, kDistance) * radial());
}

// A blob of the expected radius centred on `p` with a band as wide as the blob running away from
// it along the radial direction, as a marker band leaves a ball lying against the robot: a
// quarter of the blob's rays meet the band within the run-on reach.
cv::Mat blobAgainstBand(const Config& c, cv::Point p, const cv::Scalar& blob, const cv::Scalar& band)
{
    cv::Mat frame = greenField(c);
    const double r = expectedRadius(c, kDistance);
    cv::line(frame, p, rounded(cv::Point2d(p) + 5.0 * r * radial()), band, int(std::lround(1.6 * r)));
    cv::circle(frame, p, int(std::lround(r)), blob, cv::FILLED);
    return frame;
}

}  // namespace

class ValidationRunOnHueTest : public QObject {
    Q_OBJECT
private slots:
    // The premise: the dim ball and the dim band share the "no class" class, and the chroma step
    // (line paint: greyer, no darker) does not end a run into the band.
    void dimBallAndBandAreUnclassified()
    {
        const Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = blobAgainstBand(c, p, kDimOrange, kDimMagenta);
        const EdgeStages s(c, frame);
        QCOMPARE(int(s.classes.at<std::uint8_t>(p)), 0);
        QCOMPARE(int(s.classes.at<std::uint8_t>(onBand(c, p))), 0);
    }

    void ballAgainstAMarkerBandPassesWithTheStep()
    {
        Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = blobAgainstBand(c, p, kDimOrange, kDimMagenta);
        QVERIFY(c.validation.runOnHueStep > 0.0);
        const BallCandidate on = validateAt(c, frame, p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
        c.validation.runOnHueStep = 0.0;
        const BallCandidate off = validateAt(c, frame, p);
        QVERIFY2(off.rejected == RejectReason::RunsOn, qPrintable(verdict(off)));
        QVERIFY(off.scores.runOnPct > on.scores.runOnPct);
    }

    // The step is read from the config: a step wider than the two hues lie apart keeps the run.
    void stepFromTheConfig()
    {
        Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = blobAgainstBand(c, p, kDimOrange, kDimMagenta);
        c.validation.runOnHueStep = 60.0;  // orange (hue 15) and magenta (153): 42 apart
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::RunsOn);
        c.validation.runOnHueStep = 30.0;
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::None);
    }

    // What still runs on: a blob going on in its own hue (a leg or a robot part in its darker
    // shading), and near-grey pixels (chroma 10, a shoe below a leg), whose hue is noise: below
    // the chroma floor hues are not compared, however far apart they are.
    void ownHueAndGreyStillRunOn_data()
    {
        QTest::addColumn<cv::Scalar>("blob");
        QTest::addColumn<cv::Scalar>("band");
        QTest::newRow("magenta into darker magenta") << cv::Scalar(72, 14, 78) << kDimMagenta;
        QTest::newRow("warm grey into cool grey") << cv::Scalar(76, 81, 86) << cv::Scalar(86, 81, 76);
    }
    void ownHueAndGreyStillRunOn()
    {
        QFETCH(cv::Scalar, blob);
        QFETCH(cv::Scalar, band);
        const Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = blobAgainstBand(c, p, blob, band);
        const EdgeStages s(c, frame);
        QCOMPARE(int(s.classes.at<std::uint8_t>(p)), 0);
        QCOMPARE(int(s.classes.at<std::uint8_t>(onBand(c, p))), 0);
        const BallCandidate blobCandidate = validateAt(c, frame, p);
        QVERIFY2(blobCandidate.rejected == RejectReason::RunsOn, qPrintable(verdict(blobCandidate)));
    }

    // The chroma floor is what keeps the greys running on: without it their noise hues end the run.
    void chromaFloorFromTheConfig()
    {
        Config c;
        const cv::Point p = centreAt(c);
        const cv::Mat frame = blobAgainstBand(c, p, cv::Scalar(76, 81, 86), cv::Scalar(86, 81, 76));
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::RunsOn);
        c.validation.runOnHueMinChroma = 0.0;
        const BallCandidate noFloor = validateAt(c, frame, p);
        QVERIFY2(noFloor.rejected != RejectReason::RunsOn, qPrintable(verdict(noFloor)));
    }
};

QTEST_GUILESS_MAIN(ValidationRunOnHueTest)
#include "core_validation_run_on_hue_test.moc"
