// validation.rim_min_contrast (core/SurroundContrast.h): at the mirror's rim a patch of the hall
// floor outlined by "green" speckle passes the rim test's shape; its inside has the floor's
// colour, a ball's has its own. And hough.prefilter_rim_test: a maximum the rim test would
// refuse takes no candidate slot.
#include "DrawnCandidate.h"
#include "RimDistance.h"
#include "core/CandidatePrefilter.h"
#include "core/SurroundContrast.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {

inline const cv::Scalar kFloor(110, 110, 110);  // the hall's grey floor beyond the carpet
inline const cv::Scalar kRed(40, 40, 200);
constexpr double kSquash = 0.6;   // a spherical mirror's far ring, as tests/core_rim_test_test.cpp
constexpr double kAngle = 250.0;  // degrees

// A 60 x 60 scene for surroundContrast itself: carpet everywhere, the floor (no class) from
// x >= floorX on, and a disc of `disc` colour, radius 5 at (30, 30), of no class either.
struct Scene {
    cv::Mat frame{60, 60, CV_8UC3, kGreen};
    cv::Mat classes;
    cv::Mat used{60, 60, CV_8UC1, cv::Scalar(255)};
    ColourRoles roles{Config().colors.classes};

    Scene(int floorX, const cv::Scalar& disc)
    {
        classes = cv::Mat(60, 60, CV_8UC1, cv::Scalar(roleClassId(Config().colors.classes, ColourRole::Field)));
        const cv::Rect floor(floorX, 0, 60 - floorX, 60);
        frame(floor).setTo(kFloor);
        classes(floor).setTo(0);
        cv::circle(frame, {30, 30}, 5, disc, cv::FILLED);
        cv::circle(classes, {30, 30}, 5, cv::Scalar(0), cv::FILLED);
    }
    std::optional<double> contrast() const
    {
        return surroundContrast(FrameColour(frame, PixelFormat::Bgr8), classes, used, roles, 30, 30, 5.0);
    }
};

Config rimConfig()
{
    Config c;
    c.geometry.outerRadius = 200;  // the default ball is ~4.5 px there, as the matrix's rim balls
    c.ball.squashC0 = kSquash;
    return c;
}

// The carpet ends at the ball's inner border; the hall floor runs on past the rim. The ball
// (squashed, short axis towards the mirror centre) is filled with `fill` and outlined by a ring
// of carpet green three pixels wide, as dim noise outlines a floor patch. Returns its centre.
cv::Point drawRimScene(cv::Mat& frame, const Config& c, double distance, const cv::Scalar& fill)
{
    const double r = expectedRadius(c, distance);
    const double radialSemiAxis = r * std::sqrt(kSquash);
    cv::Mat floor(frame.size(), CV_8UC1, cv::Scalar(255));
    cv::circle(floor, cv::Point(int(std::lround(c.geometry.centerX)), int(std::lround(c.geometry.centerY))),
               int(std::lround(distance - radialSemiAxis)), cv::Scalar(0), cv::FILLED);
    frame.setTo(kFloor, floor);
    const cv::Point2d q = pointAt(c, distance, kAngle);
    const cv::Size2f axes(float(2.0 * radialSemiAxis), float(2.0 * r / std::sqrt(kSquash)));
    cv::ellipse(frame, cv::RotatedRect(q, axes + cv::Size2f(6, 6), float(-kAngle)), kGreen, cv::FILLED);
    cv::ellipse(frame, cv::RotatedRect(q, axes, float(-kAngle)), fill, cv::FILLED);
    return {int(std::lround(q.x)), int(std::lround(q.y))};
}

BallCandidate validateRimScene(const Config& c, const cv::Scalar& fill)
{
    cv::Mat frame = greenField(c);
    const cv::Point p = drawRimScene(frame, c, distanceOverhanging(c, 1.5), fill);
    return validateAt(c, frame, p);
}

}  // namespace

class SurroundContrastTest : public QObject {
    Q_OBJECT
private slots:
    // A red disc half on the floor differs from it by the three channels' steps added.
    void ballDiffersFromTheFloor()
    {
        const std::optional<double> step = Scene(30, kRed).contrast();
        QVERIFY(step.has_value());
        QVERIFY2(std::abs(*step - (70 + 70 + 90)) < 1.0, qPrintable(QString::number(*step)));
    }

    // A patch of the floor's own colour: no step.
    void floorPatchHasNoContrast()
    {
        const std::optional<double> step = Scene(30, kFloor).contrast();
        QVERIFY(step.has_value());
        QVERIFY2(*step < 1.0, qPrintable(QString::number(*step)));
    }

    // All carpet around: nothing to compare with (the carpet is not what a rim patch mimics).
    void ballInTheOpenIsNotMeasured() { QVERIFY(!Scene(60, kRed).contrast().has_value()); }

    // At the rim: a ball passes, a floor patch of the same shape does not, and passes without
    // rim_min_contrast (it is this rule that refuses it).
    void floorPatchAtTheRimIsRefused()
    {
        Config c = rimConfig();
        const BallCandidate ball = validateRimScene(c, kOrange);
        QVERIFY2(ball.rejected == RejectReason::None, qPrintable(verdict(ball)));
        const BallCandidate patch = validateRimScene(c, kFloor);
        QVERIFY2(patch.rejected == RejectReason::OutsideArea, qPrintable(verdict(patch)));
        c.validation.rimMinContrast = 0.0;
        const BallCandidate passed = validateRimScene(c, kFloor);
        QVERIFY2(passed.rejected == RejectReason::None, qPrintable(verdict(passed)));
    }

    // The threshold is the config's: a step below it refuses, at or above it passes.
    void thresholdIsRead()
    {
        Config c = rimConfig();
        c.validation.rimMinContrast = 400.0;  // more than orange's step from the grey floor
        QCOMPARE(validateRimScene(c, kOrange).rejected, RejectReason::OutsideArea);
    }

    // rimCutBallPasses is what the prefilter asks (hough.prefilter_rim_test), so the patch is
    // refused before it takes a slot, and only with the switch on.
    void prefilterAsksTheRimTest()
    {
        Config c = rimConfig();
        QVERIFY(candidatePrefilterFor(c).rimTest);
        c.hough.prefilterRimTest = false;
        QVERIFY(!candidatePrefilterFor(c).rimTest);
        c.hough.prefilterRimTest = true;
        c.validation.rimTest = false;  // no rim test to ask: every rim circle is refused anyway
        QVERIFY(!candidatePrefilterFor(c).rimTest);

        const Config on = rimConfig();
        cv::Mat frame = greenField(on);
        const double d = distanceOverhanging(on, 1.5);
        const cv::Point p = drawRimScene(frame, on, d, kFloor);
        const EdgeStages s(on, frame);
        const FrameColour colour(frame, PixelFormat::Bgr8);
        const ColourRoles roles(on.colors.classes);
        const double dist = s.geometry.distanceAt(p.x, p.y);
        const double r = s.ball.radiusAt(dist);
        QVERIFY(!rimCutBallPasses(s.classes, s.geometry, roles, p.x, p.y, dist, r, s.ball.squashAt(dist), on.validation,
                                  &colour));
        // Without the frame's colours the contrast is not asked: the shape alone passes it.
        QVERIFY(rimCutBallPasses(s.classes, s.geometry, roles, p.x, p.y, dist, r, s.ball.squashAt(dist), on.validation,
                                 nullptr));
    }
};

QTEST_APPLESS_MAIN(SurroundContrastTest)
#include "core_surround_contrast_test.moc"
