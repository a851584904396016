// Distance map (px <-> m, ball-height correction) and the ball radius model.
#include "core/BallModel.h"
#include "core/ConfigSchema.h"
#include "core/DistanceMap.h"

#include <QtTest>

using namespace omnitune;

class DistanceBallTest : public QObject {
    Q_OBJECT
private slots:
    void passesThroughCalibrationPoints()
    {
        const DistanceMapOptions o;
        const DistanceMap map(o);
        for (std::size_t i = 0; i < o.pixelRadii.size(); ++i)
            QVERIFY(std::abs(map.toGround(o.pixelRadii[i]) - o.groundDistances[i]) < 1e-9);
    }

    void isMonotoneAndInvertible()
    {
        const DistanceMap map{DistanceMapOptions{}};
        double previous = -1;
        for (double px = 0; px <= 300; px += 0.25) {
            const double m = map.toGround(px);
            QVERIFY2(m > previous, qPrintable(QString("not increasing at %1 px").arg(px)));
            previous = m;
            QVERIFY(std::abs(map.toPixels(m) - px) < 1e-4);
        }
    }

    // A straight line through the points stays a straight line (no overshoot of the cubic).
    void linearDataStaysLinear()
    {
        DistanceMapOptions o;
        o.pixelRadii = {0, 100, 200, 300};
        o.groundDistances = {0, 1, 2, 3};
        const DistanceMap map(o);
        QVERIFY(std::abs(map.toGround(150) - 1.5) < 1e-9);
        QVERIFY(std::abs(map.toGround(350) - 3.5) < 1e-9);  // extrapolated
    }

    // A map whose first point is not at 0 px goes straight to 0 m at the centre, never below.
    void neverNegativeBeforeTheFirstPoint()
    {
        DistanceMapOptions o;
        o.pixelRadii = {50, 70, 240};
        o.groundDistances = {0.30, 0.45, 6.5};
        const DistanceMap map(o);
        QCOMPARE(map.toGround(0), 0.0);
        QVERIFY(std::abs(map.toGround(25) - 0.15) < 1e-9);
        QVERIFY(map.toGround(-5) >= 0.0);
        QVERIFY(std::abs(map.toPixels(0.15) - 25) < 1e-9);  // and back
    }

    void ballHeightCorrection()
    {
        DistanceMapOptions o;
        o.viewpointHeight = 0.8;
        o.ballRadius = 0.1;
        const DistanceMap map(o);
        // The ray through the ball centre meets the ground at D * H / (H - r).
        const double px = 170;
        QVERIFY(std::abs(map.ballDistance(px) - map.toGround(px) * 0.7 / 0.8) < 1e-9);
        QVERIFY(std::abs(map.ballPixels(map.ballDistance(px)) - px) < 1e-4);
    }

    // Bad points are a user error reported once, by checkConfig() with the key; the map's
    // constructor only asserts what its tables need.
    void rejectsBadPoints_data()
    {
        QTest::addColumn<QVector<double>>("px");
        QTest::addColumn<QVector<double>>("m");
        QTest::addColumn<QString>("key");
        QTest::newRow("one point") << QVector<double>{0} << QVector<double>{0} << "distance_map.ground_distances";
        QTest::newRow("sizes differ") << QVector<double>{0, 10, 20} << QVector<double>{0, 1}
                                      << "distance_map.ground_distances";
        QTest::newRow("pixels not increasing") << QVector<double>{0, 10, 10} << QVector<double>{0, 1, 2}
                                               << "distance_map.pixel_radii";
        QTest::newRow("metres decreasing") << QVector<double>{0, 10, 20} << QVector<double>{0, 2, 1}
                                           << "distance_map.ground_distances";
    }
    void rejectsBadPoints()
    {
        QFETCH(QVector<double>, px);
        QFETCH(QVector<double>, m);
        QFETCH(QString, key);
        Config c;
        c.distanceMap.pixelRadii.assign(px.begin(), px.end());
        c.distanceMap.groundDistances.assign(m.begin(), m.end());
        const auto issues = checkConfig(c);
        QVERIFY(std::any_of(issues.begin(), issues.end(),
                            [&](const ConfigIssue& i) { return QString::fromStdString(i.key) == key; }));
    }
    void tooFewPointsAreAProgrammerError()
    {
        DistanceMapOptions o;
        o.pixelRadii = {0};
        o.groundDistances = {0};
        QVERIFY_EXCEPTION_THROWN(DistanceMap{o}, cv::Exception);
    }

    void radiusIsThePolynomialClamped()
    {
        BallModelOptions o;
        o.c0 = 30;
        o.c1 = -0.1;
        o.c2 = 0.0001;
        o.minRadius = 3;
        o.maxRadius = 25;
        const BallModel ball(o);
        QCOMPARE(ball.radiusAt(100), 30 - 10 + 1.0);
        QCOMPARE(ball.radiusAt(0), 25.0);    // clamped high
        QCOMPARE(ball.radiusAt(1000), 25.0); // polynomial grows again far out: clamped
        o.c2 = 0;
        const BallModel linear(o);
        QCOMPARE(linear.radiusAt(400), 3.0); // clamped low
    }

    void defaultModelShrinksWithDistance()
    {
        const BallModel ball(BallModelOptions{});
        double previous = 1e9;
        for (int d = 50; d <= 240; d += 10) {
            const double r = ball.radiusAt(d);
            QVERIFY(r <= previous);
            previous = r;
        }
        QVERIFY(ball.radiusAt(60) > 20);  // engaged ball near the robot
        QVERIFY(ball.radiusAt(240) <= 4);
    }

    void squareIsOddAndScalesWithTheBall()
    {
        const BallModel ball(BallModelOptions{});
        for (int d = 0; d <= 300; d += 7) {
            const int side = ball.squareSizeAt(d);
            QCOMPARE(side % 2, 1);
            QVERIFY(side >= 3);
            QVERIFY(side <= int(2 * ball.radiusAt(d)) + 1);
        }
        QVERIFY(ball.squareSizeAt(60) > ball.squareSizeAt(200));
    }
};

QTEST_GUILESS_MAIN(DistanceBallTest)
#include "core_distance_ball_test.moc"
