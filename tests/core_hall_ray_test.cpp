// validation.hall_rays_by_colour (core/HallRay.h): a far ball at the carpet's edge lies half over
// the hall floor, which the binary image does not part from it; its rays over the floor are
// judged by colour, so it is round again, while a floor patch with no ball stays not round.
#include "DrawnCandidate.h"
#include "core/HallRay.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {

inline const cv::Scalar kFloor(110, 110, 110);  // the hall's grey floor beyond the carpet
// A red ball: of no colour class, as most balls. (An orange one has its ball class, and its rays
// into the floor are left out as a foreign contact, validation.foreign_rays_unknown.)
inline const cv::Scalar kRed(40, 40, 200);
constexpr double kAngle = 300.0;                 // degrees; any direction serves

// The carpet ends `edgePx` from the mirror centre; the floor runs on out past the rim.
void paintFloorFrom(cv::Mat& frame, const Config& c, double edgePx)
{
    cv::Mat ring(frame.size(), CV_8UC1, cv::Scalar(255));
    cv::circle(ring, cv::Point(int(std::lround(c.geometry.centerX)), int(std::lround(c.geometry.centerY))),
               int(std::lround(edgePx)), cv::Scalar(0), cv::FILLED);
    frame.setTo(kFloor, ring);
}

// A ball at `distance` whose outer half lies over the floor beyond the carpet's edge there.
Config edgeConfig(bool hallRays)
{
    Config c;
    // The default ball model's ball is ~5 px at 185 px; the rim 15 px beyond.
    c.geometry.outerRadius = 200;
    c.validation.hallRaysByColour = hallRays;
    return c;
}

// Pixels of a hand-made 40 x 40 scene for hallRay itself: x >= rimX is past the mirror's rim,
// carpet is where `carpetMask` is set, a masked column where `maskX` is.
struct TestPixels : HallPixels {
    cv::Mat bgrImage;
    cv::Mat carpetMask;
    int rimX = 36;
    int maskX = -1;
    bool known(cv::Point p) const override
    {
        return p.x >= 0 && p.y >= 0 && p.x < rimX && p.y < bgrImage.rows && p.x != maskX;
    }
    bool carpet(cv::Point p) const override { return carpetMask.at<std::uint8_t>(p) != 0; }
    bool pastRim(cv::Point p) const override { return p.x >= rimX; }
    std::array<std::uint8_t, 3> bgr(cv::Point p) const override
    {
        const cv::Vec3b v = bgrImage.at<cv::Vec3b>(p);
        return {v[0], v[1], v[2]};
    }
};

TestPixels floorScene(const cv::Scalar& ball)
{
    TestPixels px;
    px.bgrImage = cv::Mat(40, 40, CV_8UC3, kFloor);
    px.carpetMask = cv::Mat::zeros(40, 40, CV_8UC1);
    cv::circle(px.bgrImage, {20, 20}, 5, ball, cv::FILLED);
    return px;
}

}  // namespace

class HallRayTest : public QObject {
    Q_OBJECT
private slots:
    // Towards the rim over the floor: the border is where the ball's orange ends.
    void rayOverTheFloorFindsTheBallsBorder()
    {
        const TestPixels px = floorScene(kOrange);
        const HallRay ray = hallRay({{20, 20}, 1.0, 0.0, 9.0}, 4.0, 20.0, 40.0, px);
        QVERIFY(ray.overFloor);
        QVERIFY(ray.border);
        QVERIFY2(std::abs(ray.borderPx - 5.5) <= 0.5, qPrintable(QString::number(ray.borderPx)));
    }

    // The same ray with carpet between the band and the rim is no hall ray; a speck is.
    void carpetBeforeTheRimIsNoHall()
    {
        TestPixels px = floorScene(kOrange);
        px.carpetMask.at<std::uint8_t>(20, 31) = 255;  // one carpet pixel: noise
        QVERIFY(hallRay({{20, 20}, 1.0, 0.0, 9.0}, 4.0, 20.0, 40.0, px).overFloor);
        px.carpetMask.at<std::uint8_t>(20, 32) = 255;  // two in a row: carpet
        QVERIFY(!hallRay({{20, 20}, 1.0, 0.0, 9.0}, 4.0, 20.0, 40.0, px).overFloor);
    }

    // A masked pixel (a rod, our body) before the rim, or a rim beyond the reach: no hall ray.
    void maskOrFarRimIsNoHall()
    {
        TestPixels px = floorScene(kOrange);
        px.maskX = 33;
        QVERIFY(!hallRay({{20, 20}, 1.0, 0.0, 9.0}, 4.0, 20.0, 40.0, px).overFloor);
        px.maskX = -1;
        QVERIFY(!hallRay({{20, 20}, 1.0, 0.0, 9.0}, 4.0, 5.0, 40.0, px).overFloor);
    }

    // Over the floor but of the floor's own colour (a floor patch), a ball too small for the band,
    // or colour running on past the band's end: over the floor, with no border.
    void noColourStepIsNoBorder()
    {
        const TestPixels grey = floorScene(kFloor + cv::Scalar(10, 10, 10));
        const HallRay patch = hallRay({{20, 20}, 1.0, 0.0, 9.0}, 4.0, 20.0, 40.0, grey);
        QVERIFY(patch.overFloor);
        QVERIFY(!patch.border);
        const HallRay small = hallRay({{20, 20}, 1.0, 0.0, 9.0}, 7.0, 20.0, 40.0, floorScene(kOrange));
        QVERIFY(small.overFloor);
        QVERIFY(!small.border);
        const HallRay runsOn = hallRay({{20, 20}, 1.0, 0.0, 4.0}, 2.0, 20.0, 40.0, floorScene(kOrange));
        QVERIFY(runsOn.overFloor);
        QVERIFY(!runsOn.border);
    }

    // The whole validation: the far ball at the carpet's edge passes with the rule and fails as
    // not round without it; a grey-floor blob of the ball's size does not pass with it.
    void farBallAtTheCarpetsEdge()
    {
        const double d = 185.0;
        const Config on = edgeConfig(true);
        cv::Mat frame = greenField(on);
        paintFloorFrom(frame, on, d);
        const cv::Point2d q = pointAt(on, d, kAngle);
        const cv::Point p(int(std::lround(q.x)), int(std::lround(q.y)));
        const int r = int(std::lround(expectedRadius(on, d)));
        cv::Mat ball = frame.clone();
        cv::circle(ball, p, r, kRed, cv::FILLED);
        const BallCandidate judged = validateAt(on, ball, p);
        QVERIFY2(judged.rejected == RejectReason::None, qPrintable(verdict(judged)));
        const BallCandidate off = validateAt(edgeConfig(false), ball, p);
        QVERIFY2(off.rejected == RejectReason::Circularity, qPrintable(verdict(off)));
        // The floor's own bulge into the carpet, the ball's size, of the floor's colour.
        cv::Mat bulge = frame.clone();
        cv::circle(bulge, p, r, kFloor, cv::FILLED);
        const BallCandidate floor = validateAt(on, bulge, p);
        QVERIFY2(floor.rejected == RejectReason::Circularity, qPrintable(verdict(floor)));
    }

    // hall_colour_step, hall_reach_radii and hall_outward_cos are read from the config: a step past
    // the ball's own difference from the floor, a reach short of the rim, or a cone too narrow to
    // hold a ray, leaves it not round.
    void thresholdsAreTheConfigs()
    {
        const double d = 185.0;
        Config c = edgeConfig(true);
        cv::Mat frame = greenField(c);
        paintFloorFrom(frame, c, d);
        const cv::Point2d q = pointAt(c, d, kAngle);
        const cv::Point p(int(std::lround(q.x)), int(std::lround(q.y)));
        cv::circle(frame, p, int(std::lround(expectedRadius(c, d))), kRed, cv::FILLED);
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::None);
        c.validation.hallColourStep = 765;
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::Circularity);
        c.validation.hallColourStep = 40;
        c.validation.hallReachRadii = 0.5;
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::Circularity);
        c.validation.hallReachRadii = 4;
        c.validation.hallOutwardCos = 1.0;
        QCOMPARE(validateAt(c, frame, p).rejected, RejectReason::Circularity);
    }
};

QTEST_APPLESS_MAIN(HallRayTest)
#include "core_hall_ray_test.moc"
