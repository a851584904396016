// validation.min_circularity_clear_pct (issue 9): a candidate in the clear (its square mostly
// non-black, so no robot hides it, and at least clear_min_radius_px) is judged on its whole
// border, and blur or noise cost a ball a few rays below the thesis' 70 %; it passes at 60 %.
// A candidate beside black keeps 70 %: its rays into the robot are left out and the robot's
// outline is what the others see; so does one of a far line junction's size, and one whose
// fitted circle is not the expected size (validation.clear_max_fit_error). Drawn here: an
// orange ball whose edges are erased over one sector, so that about a third of its rays find
// no border.
#include "DrawnCandidate.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {

constexpr double kDistance = 120;  // px from the robot centre (a ball of ~10 px with the default model)
constexpr double kAngle = 40;      // degrees

// The orange ball at kDistance, validated under `c` on edges erased over `lostDeg` degrees of its
// border (the sector facing +x): those rays meet no edge, as where blur washed the border out.
BallCandidate ballWithBorderLost(const Config& c, double lostDeg)
{
    cv::Mat frame = greenField(c);
    const cv::Point2d p = pointAt(c, kDistance, kAngle);
    const cv::Point centre(int(std::lround(p.x)), int(std::lround(p.y)));
    const double r = expectedRadius(c, kDistance);
    cv::circle(frame, centre, int(std::lround(r)), kOrange, cv::FILLED);
    const EdgeStages s(c, frame);
    cv::Mat edges = s.edges.clone();
    const int reach = int(std::ceil(2.0 * r));
    cv::ellipse(edges, centre, {reach, reach}, 0, -lostDeg / 2, lostDeg / 2, cv::Scalar(0), cv::FILLED);
    BallCandidate cand;
    cand.x = centre.x;
    cand.y = centre.y;
    cand.distancePx = s.geometry.distanceAt(centre.x, centre.y);
    cand.expectedRadiusPx = s.ball.radiusAt(cand.distancePx);
    validateCandidate(cand, s.classes, edges, s.geometry, s.ball, c.validation);
    return cand;
}

}  // namespace

class ClearCircularityTest : public QObject {
    Q_OBJECT
private slots:
    void requiredShare_data()
    {
        QTest::addColumn<double>("nonBlackPct");
        QTest::addColumn<double>("radiusPx");
        QTest::addColumn<double>("fitRadiusPx");
        QTest::addColumn<double>("clearPct");
        QTest::addColumn<double>("required");
        QTest::newRow("in the clear") << 100.0 << 10.0 << 10.0 << 60.0 << 60.0;
        QTest::newRow("at clear_min_non_black_pct") << 60.0 << 10.0 << 10.0 << 60.0 << 60.0;
        QTest::newRow("beside a robot") << 59.0 << 10.0 << 10.0 << 60.0 << 70.0;
        QTest::newRow("at clear_min_radius_px") << 100.0 << 9.0 << 9.0 << 60.0 << 60.0;
        QTest::newRow("far: a line junction's size") << 100.0 << 8.9 << 8.9 << 60.0 << 70.0;
        QTest::newRow("fit 1.5 px large: at clear_max_fit_error") << 100.0 << 10.0 << 11.5 << 60.0 << 60.0;
        QTest::newRow("fit 1.5 px small: at clear_max_fit_error") << 100.0 << 10.0 << 8.5 << 60.0 << 60.0;
        QTest::newRow("fit 1.6 px small: not the ball's size") << 100.0 << 10.0 << 8.4 << 60.0 << 70.0;
        QTest::newRow("fit 2.2 px large: not the ball's size") << 100.0 << 10.0 << 12.2 << 60.0 << 70.0;
        QTest::newRow("switched off (thesis)") << 100.0 << 10.0 << 10.0 << 70.0 << 70.0;
        QTest::newRow("never stricter than min_circularity_pct") << 100.0 << 10.0 << 10.0 << 80.0 << 70.0;
    }
    void requiredShare()
    {
        QFETCH(double, nonBlackPct);
        QFETCH(double, radiusPx);
        QFETCH(double, fitRadiusPx);
        QFETCH(double, clearPct);
        QFETCH(double, required);
        ValidationOptions o;
        QCOMPARE(o.minCircularityPct, 70.0);
        QCOMPARE(o.clearMinNonBlackPct, 60.0);
        QCOMPARE(o.clearMinRadiusPx, 9.0);
        QCOMPARE(o.clearMaxFitError, 0.15);
        o.minCircularityClearPct = clearPct;
        BallCandidate c;
        c.expectedRadiusPx = radiusPx;
        c.scores.nonBlackPct = nonBlackPct;
        c.scores.fitRadiusPx = fitRadiusPx;
        QCOMPARE(requiredCircularityPct(c, o), required);
    }

    // A third of the border lost (120 degrees): between the two thresholds. In the clear it passes; with the
    // rule off (the thesis' one threshold) it fails circularity.
    void clearBallBetweenTheThresholdsPasses()
    {
        Config c;
        const BallCandidate on = ballWithBorderLost(c, 120);
        QVERIFY2(on.scores.circularityPct >= c.validation.minCircularityClearPct &&
                     on.scores.circularityPct < c.validation.minCircularityPct,
                 qPrintable(verdict(on)));
        QVERIFY2(on.scores.nonBlackPct >= c.validation.clearMinNonBlackPct, qPrintable(verdict(on)));
        QVERIFY2(on.expectedRadiusPx >= c.validation.clearMinRadiusPx, qPrintable(verdict(on)));
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));

        c.validation.minCircularityClearPct = c.validation.minCircularityPct;
        const BallCandidate off = ballWithBorderLost(c, 120);
        QVERIFY2(off.rejected == RejectReason::Circularity, qPrintable(verdict(off)));
    }

    // Below the clear threshold the ball still fails: the rule moves the bar, it does not drop it.
    void clearBallBelowTheClearThresholdFails()
    {
        const Config c;
        const BallCandidate b = ballWithBorderLost(c, 150);
        QVERIFY2(b.scores.circularityPct < c.validation.minCircularityClearPct, qPrintable(verdict(b)));
        QVERIFY2(b.rejected == RejectReason::Circularity, qPrintable(verdict(b)));
    }
};

QTEST_GUILESS_MAIN(ClearCircularityTest)
#include "core_validation_clear_circularity_test.moc"
