// A ball at a person's feet or beside a robot's grey side (core/ForeignContact,
// validation.foreign_rays_unknown): when the candidate's centre has a ball class, the rays that
// leave it into an object that is neither carpet nor line are left out of the circularity, so
// the ball passes on the rays that open onto carpet; blobs without the ball's class, and a ball
// spot swallowed by an object, get no such allowance.
#include "DrawnCandidate.h"
#include "core/ForeignContact.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {

constexpr double kDistance = 120.0;  // px from the robot centre: a ball of ~10 px radius
constexpr double kAngle = 30.0;      // degrees
const cv::Scalar kGrey(110, 110, 110);  // trousers: no class (neither carpet, line nor black)
const cv::Scalar kCyan(200, 170, 20);   // a robot's cyan marker: a marker class

template <class Draw>
BallCandidate validateDrawn(const Config& c, Draw draw)
{
    return omnitune::test::validateDrawn(c, kDistance, kAngle, draw);
}

// An orange ball of radius r at p against an object of colour `object` that covers a third of
// its outline: a leg standing on the ball's upper left (kind 0), or a block beside it (kind 1).
void drawBallAgainst(cv::Mat& f, cv::Point p, double r, const cv::Scalar& object, int kind)
{
    const int ri = int(std::lround(r));
    if (kind == 0)
        cv::line(f, p + cv::Point(-ri / 2, -ri / 2), p + cv::Point(-5 * ri, -5 * ri), object, int(2.4 * r));
    else
        cv::rectangle(f, p + cv::Point(int(0.7 * r), -3 * ri), p + cv::Point(5 * ri, 3 * ri), object, cv::FILLED);
    cv::circle(f, p, ri, kOrange, cv::FILLED);
}

}  // namespace

class ForeignContactTest : public QObject {
    Q_OBJECT

private slots:
    void ballAgainstObjectPasses_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("cyan");
        QTest::newRow("grey leg") << 0 << false;
        QTest::newRow("grey block") << 1 << false;
        QTest::newRow("cyan block") << 1 << true;
    }
    void ballAgainstObjectPasses()
    {
        QFETCH(int, kind);
        QFETCH(bool, cyan);
        // A cyan block is a team marker: marker_rays_unknown alone would pass the ball. Off, so
        // that this rule is the one measured. So would the clear threshold (68-70 % without this
        // rule): every candidate is held to min_circularity_pct here.
        Config c;
        c.validation.markerRaysUnknown = !cyan;
        c.validation.minCircularityClearPct = c.validation.minCircularityPct;
        checkRuleAcceptsIt(c, &ValidationOptions::foreignRaysUnknown, kDistance, kAngle,
                           [&](cv::Mat& f, cv::Point p, double r) { drawBallAgainst(f, p, r, cyan ? kCyan : kGrey, kind); });
    }

    // Look-alikes stay rejected: a grey blob the size of a ball beside a grey block (its centre
    // has no ball class), and an orange spot inside a grey region (every ray leaves it into the
    // object: none is left to judge it by).
    void withoutTheBallsClassNoAllowance_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("grey disc against a grey block") << 0;
        QTest::newRow("orange spot inside grey") << 1;
    }
    void withoutTheBallsClassNoAllowance()
    {
        QFETCH(int, kind);
        const Config c;
        const BallCandidate cand = validateDrawn(c, [kind](cv::Mat& f, cv::Point p, double r) {
            const int ri = int(std::lround(r));
            if (kind == 1) {
                cv::circle(f, p, 3 * ri, kGrey, cv::FILLED);
                cv::circle(f, p, ri, kOrange, cv::FILLED);
                return;
            }
            cv::rectangle(f, p + cv::Point(int(0.7 * r), -3 * ri), p + cv::Point(5 * ri, 3 * ri), kGrey, cv::FILLED);
            cv::circle(f, p, ri, kGrey, cv::FILLED);
        });
        QVERIFY2(cand.rejected != RejectReason::None, qPrintable(verdict(cand)));
    }

    // The ray itself, on a class image: it meets an object only when it crossed the ball's class
    // alone out to min entry and the object goes on to the reach.
    void rayMeetsObjectOnlyWhenItGoesOn_data()
    {
        QTest::addColumn<int>("objectFrom");  // px from the centre where the object starts
        QTest::addColumn<int>("objectTo");    // ... and where carpet takes over
        QTest::addColumn<bool>("ballCentre"); // the centre has the ball class
        QTest::addColumn<bool>("contact");
        QTest::newRow("object from the border on") << 10 << 40 << true << true;
        QTest::newRow("blend at the border") << 10 << 12 << true << false;
        QTest::newRow("object near the centre") << 3 << 40 << true << false;
        QTest::newRow("no ball class at the centre") << 10 << 40 << false << false;
    }
    void rayMeetsObjectOnlyWhenItGoesOn()
    {
        QFETCH(int, objectFrom);
        QFETCH(int, objectTo);
        QFETCH(bool, ballCentre);
        QFETCH(bool, contact);
        const Config c;
        const Geometry geometry(c.geometry, c.mask);
        const ColourRoles roles(c.colors.classes);
        const auto id = [&](ColourRole role) { return roleClassId(c.colors.classes, role); };
        const cv::Point2d p = pointAt(c, kDistance, kAngle);
        const int x = int(p.x);
        const int y = int(p.y);
        const double radius = 10.0;
        cv::Mat classes(c.geometry.imageHeight, c.geometry.imageWidth, CV_8UC1, cv::Scalar(id(ColourRole::Field)));
        cv::circle(classes, {x, y}, int(radius), cv::Scalar(ballCentre ? id(ColourRole::Ball) : 0), cv::FILLED);
        for (int d = objectFrom; d < objectTo; ++d) classes.at<std::uint8_t>(y, x + d) = 0;  // no class
        const ColorClass ball = ballClassAt(classes, roles, x, y);
        QCOMPARE(ball != ColorClass::Unknown, ballCentre);
        const ValidationOptions& o = c.validation;
        ForeignContactRay ray(classes, geometry, roles, ball, x, y, 1.0, 0.0, o.lineContactMinEntry * radius,
                              o.lineContactReach * radius);
        const bool met = walkRayAlongX(x, y, 2.0 * radius, [&](cv::Point q, double r) { return ray.entersObject(q, r); });
        QCOMPARE(met, contact);
    }
};

QTEST_GUILESS_MAIN(ForeignContactTest)
#include "core_foreign_contact_test.moc"
