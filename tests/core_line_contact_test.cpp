// A ball touching a field line (core/LineContact, validation.line_rays_unknown): the rays that
// leave the ball into the line are left out of the circularity, so the ball passes on the rays
// that open onto carpet; line corners, line ends and white panels ending at the ball's border get
// no such allowance.
#include "DrawnCandidate.h"
#include "core/LineContact.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;
Q_DECLARE_METATYPE(omnitune::RejectReason)

namespace {

constexpr double kDistance = 120.0;  // px from the robot centre: a ball of ~10 px radius
constexpr double kAngle = 30.0;      // degrees

template <class Draw>
BallCandidate validateDrawn(const Config& c, Draw draw)
{
    return omnitune::test::validateDrawn(c, kDistance, kAngle, draw);
}

// An orange ball of radius r at p lying on the edge of a line as wide as a field line (~1.1 ball
// radii), as a ball the simulator calls "touching a line" does: `kind` 0 the line's near side
// 0.3 radii from the ball's centre, 1 a T junction (the line's side 0.6 radii from the centre, a
// second line ending at the ball), 2 two lines crossing under the ball's edge.
void drawBallOnLine(cv::Mat& f, cv::Point p, double r, int kind)
{
    const int ri = int(std::lround(r));
    const int w = int(std::lround(1.1 * r));
    const int off = int(std::lround((kind == 0 ? 0.3 : 0.6) * r)) + w / 2;  // the line's middle
    cv::line(f, p + cv::Point(-60, off), p + cv::Point(60, off), kWhite, w);
    if (kind == 1) cv::line(f, p + cv::Point(0, -ri), p + cv::Point(0, -60), kWhite, w);
    if (kind == 2) cv::line(f, p + cv::Point(off, -60), p + cv::Point(off, 60), kWhite, w);
    cv::circle(f, p, ri, kOrange, cv::FILLED);
}

}  // namespace

class LineContactTest : public QObject {
    Q_OBJECT

private slots:
    // The thesis' binary image makes ball and line one blob: the rays into the line find no
    // border and the ball fails circularity. Left out, the ball passes.
    void ballTouchingLinePasses_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("line along one side") << 0;
        QTest::newRow("T junction at the ball") << 1;
        QTest::newRow("line under the ball's edge") << 2;
    }
    void ballTouchingLinePasses()
    {
        QFETCH(int, kind);
        checkRuleAcceptsIt(Config{}, &ValidationOptions::lineRaysUnknown, kDistance, kAngle,
                           [kind](cv::Mat& f, cv::Point p, double r) { drawBallOnLine(f, p, r, kind); });
    }

    // Look-alikes stay rejected: a junction of two lines as wide as the ball whose centre pixel is
    // unclassified (the blurred grey of a far corner), and an orange spot inside a wide line
    // (every ray leaves it into the line: no ray is left to judge it by).
    void linesAloneGetNoAllowance_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("line corner, grey centre") << 0;
        QTest::newRow("orange spot inside a line") << 1;
    }
    void linesAloneGetNoAllowance()
    {
        QFETCH(int, kind);
        const Config c;
        const BallCandidate cand = validateDrawn(c, [kind](cv::Mat& f, cv::Point p, double r) {
            const int ri = int(std::lround(r));
            if (kind == 1) {
                cv::line(f, p - cv::Point(60, 0), p + cv::Point(60, 0), kWhite, 3 * ri);
                cv::circle(f, p, ri, kOrange, cv::FILLED);
                return;
            }
            cv::line(f, p, p + cv::Point(60, 0), kWhite, 2 * ri);
            cv::line(f, p, p + cv::Point(-10, 60), kWhite, 2 * ri);
            cv::circle(f, p, 1, cv::Scalar(128, 128, 128), cv::FILLED);  // no class
        });
        QVERIFY2(cand.rejected != RejectReason::None, qPrintable(verdict(cand)));
    }

    // The ray itself, on a class image: it meets a line only when it crossed the candidate's
    // colours alone out to min entry and the line goes on to the reach.
    void rayMeetsLineOnlyWhenItGoesOn_data()
    {
        QTest::addColumn<int>("lineFrom");   // px from the centre where the line class starts
        QTest::addColumn<int>("lineTo");     // ... and where it ends (carpet beyond)
        QTest::addColumn<int>("greenAt");    // a carpet pixel on the way in (-1: none)
        QTest::addColumn<bool>("contact");
        QTest::newRow("line from the border on") << 10 << 40 << -1 << true;
        QTest::newRow("white panel ending at the border") << 7 << 11 << -1 << false;
        QTest::newRow("line starting near the centre") << 3 << 40 << -1 << false;
        QTest::newRow("carpet before the line") << 10 << 40 << 6 << false;
    }
    void rayMeetsLineOnlyWhenItGoesOn()
    {
        QFETCH(int, lineFrom);
        QFETCH(int, lineTo);
        QFETCH(int, greenAt);
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
        cv::circle(classes, {x, y}, int(radius), cv::Scalar(id(ColourRole::Ball)), cv::FILLED);
        for (int d = lineFrom; d < lineTo; ++d) classes.at<std::uint8_t>(y, x + d) = id(ColourRole::Line);
        if (greenAt >= 0) classes.at<std::uint8_t>(y, x + greenAt) = id(ColourRole::Field);
        const ValidationOptions& o = c.validation;
        LineContactRay ray(classes, geometry, roles, x, y, 1.0, 0.0, o.lineContactMinEntry * radius,
                           o.lineContactReach * radius);
        const bool met = walkRayAlongX(x, y, 2.0 * radius, [&](cv::Point q, double r) { return ray.entersLine(q, r); });
        QCOMPARE(met, contact);
    }
};

QTEST_GUILESS_MAIN(LineContactTest)
#include "core_line_contact_test.moc"
