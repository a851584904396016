// The scene simulator: deterministic frames, ground truth that agrees with the distance map and
// ball model, colours the default LUT classifies as intended, balls that pass the colour part of
// the thesis' validation, and the Tour.
#include "core/ColorLut.h"
#include "calib/sim/SceneSimulator.h"
#include "calib/sim/Tour.h"

#include <QtTest>

#include <cmath>

using namespace omnitune;
Q_DECLARE_METATYPE(omnitune::BallKind)
Q_DECLARE_METATYPE(omnitune::ColorClass)

namespace {

// Image point seen at robot-frame direction `angle` (rad, from image +x, y up) and image radius rho.
cv::Point imagePoint(const Config& c, double rho, double angle)
{
    return {int(std::lround(c.geometry.centerX + rho * std::cos(angle))),
            int(std::lround(c.geometry.centerY - rho * std::sin(angle)))};
}

// Share (%) of the pixels in the square of odd side `side` centred on `centre` whose class is `cls`.
double classShare(const cv::Mat& frame, const ColorLut& lut, cv::Point centre, int side, ColorClass cls)
{
    int hits = 0, total = 0;
    for (int y = centre.y - side / 2; y <= centre.y + side / 2; ++y)
        for (int x = centre.x - side / 2; x <= centre.x + side / 2; ++x) {
            const cv::Vec3b p = frame.at<cv::Vec3b>(y, x);
            hits += lut.classifyBgr(p[0], p[1], p[2]) == cls;
            ++total;
        }
    return 100.0 * hits / total;
}

// A robot on open carpet (no line within ~0.7 m of where the tests put the ball).
SceneOptions openCarpet(double ballDistance, double heading = 1.0)
{
    SceneOptions s;
    s.robot = {-4.5, 0.5, heading};
    const double a = -100 * M_PI / 180;  // field direction of the ball from the robot
    s.ballX = s.robot.x + ballDistance * std::cos(a);
    s.ballY = s.robot.y + ballDistance * std::sin(a);
    return s;
}

}  // namespace

class SceneSimulatorTest : public QObject {
    Q_OBJECT
private slots:
    void sameSeedSameBytes()
    {
        const Config c;
        SceneOptions s;
        s.robot = {0.5, -0.3, 0.7};
        s.obstacles = {{2.0, 1.0, 0.25, 0.8, 1}, {-1.5, -1.5, 0.25, 0.8, 2}};
        s.humanFeet = s.headShadow = true;
        s.motionBlurPx = 4;
        s.occlusion = 0.3;
        s.lightGradient = 0.5;
        s.seed = 11;
        const cv::Mat a = SceneSimulator(c).render(s);
        const cv::Mat b = SceneSimulator(c).render(s);
        QCOMPARE(a.type(), CV_8UC3);
        QCOMPARE(a.cols, c.geometry.imageWidth);
        QCOMPARE(a.rows, c.geometry.imageHeight);
        QCOMPARE(cv::norm(a, b, cv::NORM_INF), 0.0);
        s.seed = 12;
        QVERIFY(cv::norm(a, SceneSimulator(c).render(s), cv::NORM_INF) > 0.0);
    }

    // The image is the robot frame seen from above: forward up, the robot's right to image +x.
    void headingMapsFieldToImage_data()
    {
        QTest::addColumn<double>("heading");
        QTest::addColumn<double>("ballX");
        QTest::addColumn<double>("ballY");
        QTest::addColumn<double>("imageAngleDeg");
        QTest::newRow("ahead, heading +x") << 0.0 << 2.0 << 0.0 << 90.0;
        QTest::newRow("field +y, heading +x: robot's left") << 0.0 << 0.0 << 2.0 << 180.0;
        QTest::newRow("ahead, heading +y") << M_PI / 2 << 0.0 << 2.0 << 90.0;
        QTest::newRow("field +x, heading +y: robot's right") << M_PI / 2 << 2.0 << 0.0 << 0.0;
        QTest::newRow("behind, heading -x") << M_PI << 2.0 << 0.0 << -90.0;
    }
    void headingMapsFieldToImage()
    {
        QFETCH(double, heading);
        QFETCH(double, ballX);
        QFETCH(double, ballY);
        QFETCH(double, imageAngleDeg);
        const Config c;
        SceneOptions s;
        s.robot = {0, 0, heading};
        s.ballX = ballX;
        s.ballY = ballY;
        const GroundTruth t = SceneSimulator(c).groundTruth(s);
        const double angle = std::atan2(c.geometry.centerY - t.py, t.px - c.geometry.centerX) * 180 / M_PI;
        QVERIFY2(std::abs(std::remainder(angle - imageAngleDeg, 360.0)) < 1e-6, qPrintable(QString::number(angle)));
        QVERIFY(std::abs(std::atan2(t.yM, t.xM) * 180 / M_PI - angle) < 1e-6);
    }

    void truthMatchesDistanceMapAndBallModel_data()
    {
        QTest::addColumn<double>("distance");
        QTest::addColumn<double>("heading");
        for (double d : {0.6, 1.0, 2.0, 3.0, 4.0})
            for (double heading : {0.0, 2.2})
                QTest::newRow(qPrintable(QString("%1 m, heading %2").arg(d).arg(heading))) << d << heading;
    }
    void truthMatchesDistanceMapAndBallModel()
    {
        QFETCH(double, distance);
        QFETCH(double, heading);
        const Config c;
        const SceneSimulator sim(c);
        const SceneOptions s = openCarpet(distance, heading);
        GroundTruth t;
        const cv::Mat frame = sim.render(s, &t);

        const DistanceMap map(c.distanceMap);
        const BallModel model(c.ball);
        const cv::Point2d robotFrame = toRobotFrame(s.robot, {s.ballX, s.ballY});
        QVERIFY(std::abs(t.distanceM - distance) < 1e-9);
        QVERIFY(std::abs(t.xM - robotFrame.x) < 1e-9 && std::abs(t.yM - robotFrame.y) < 1e-9);
        QVERIFY(std::abs(t.distancePx - map.ballPixels(distance)) < 1e-9);
        QVERIFY(std::abs(std::hypot(t.px - c.geometry.centerX, t.py - c.geometry.centerY) - t.distancePx) < 1e-9);
        QVERIFY(std::abs(t.radiusPx - model.radiusAt(t.distancePx)) < 1e-9);
        QVERIFY(std::abs(map.ballDistance(t.distancePx) - distance) < 1e-6);  // what the pipeline inverts
        QVERIFY(t.ballVisible);
        QVERIFY(t.visibleFraction > 0.99);
        QCOMPARE(t.pose.heading, heading);

        // The drawn disc is where the truth says: non-green pixels' centroid and area.
        const ColorLut lut(c.colors);
        const int half = int(std::ceil(t.radiusPx)) + 4;
        double sx = 0, sy = 0, n = 0;
        for (int y = int(t.py) - half; y <= int(t.py) + half; ++y)
            for (int x = int(t.px) - half; x <= int(t.px) + half; ++x) {
                const cv::Vec3b p = frame.at<cv::Vec3b>(y, x);
                if (lut.classifyBgr(p[0], p[1], p[2]) == ColorClass::Green) continue;
                sx += x, sy += y, ++n;
            }
        const double area = M_PI * t.radiusPx * t.radiusPx;
        QVERIFY2(std::abs(n - area) < 0.1 * area + 2, qPrintable(QString("%1 px vs %2").arg(n).arg(area)));
        QVERIFY2(std::hypot(sx / n - t.px, sy / n - t.py) < 0.35,
                 qPrintable(QString("centroid (%1, %2) vs (%3, %4)").arg(sx / n).arg(sy / n).arg(t.px).arg(t.py)));
    }

    // What the detector relies on, pixel by pixel, with the default LUT.
    void defaultLutClassifiesTheScene_data()
    {
        QTest::addColumn<QString>("what");
        QTest::addColumn<ColorClass>("expected");
        QTest::newRow("orange ball centre") << "ball" << ColorClass::Orange;
        QTest::newRow("carpet far from lines") << "carpet" << ColorClass::Green;
        QTest::newRow("centre circle line") << "line" << ColorClass::White;
        QTest::newRow("obstacle body") << "obstacle" << ColorClass::Black;
        QTest::newRow("cyan marker") << "cyan" << ColorClass::Cyan;
        QTest::newRow("magenta marker") << "magenta" << ColorClass::Magenta;
    }
    void defaultLutClassifiesTheScene()
    {
        QFETCH(QString, what);
        QFETCH(ColorClass, expected);
        const Config c;
        const DistanceMap map(c.distanceMap);
        const double H = c.distanceMap.viewpointHeight;
        SceneOptions s;
        s.robot = {0, 0, 0};  // on the centre spot: the centre circle is 2 m away all round
        const cv::Point2d ball = toFieldFrame(s.robot, {-1.0, 1.0});
        s.ballX = ball.x;
        s.ballY = ball.y;
        // Two marked robots 1.8 m away at image angles 0 and -90 deg.
        const cv::Point2d right = toFieldFrame(s.robot, {1.8, 0.0});
        const cv::Point2d down = toFieldFrame(s.robot, {0.0, -1.8});
        s.obstacles = {{right.x, right.y, 0.25, 0.8, 1}, {down.x, down.y, 0.25, 0.8, 2}};
        GroundTruth t;
        const cv::Mat frame = SceneSimulator(c).render(s, &t);
        // A ray meets a robot's near face (1.55 m) at height z where the ground is 1.55 / (1 - z / H).
        const double nearFace = 1.8 - 0.25;
        const auto seenAtHeight = [&](double z) { return map.toPixels(nearFace / (1 - z / H)); };

        // Where to look, and how big a square (the line is ~5 px wide there, markers ~8 px).
        cv::Point at;
        int side = 5;
        if (what == "ball") {
            at = {int(std::lround(t.px)), int(std::lround(t.py))};
            side = 3;
        } else if (what == "carpet") {
            at = imagePoint(c, map.toPixels(1.0), M_PI / 4);
        } else if (what == "line") {
            at = imagePoint(c, map.toPixels(2.0), M_PI / 4);
            side = 1;
        } else if (what == "obstacle") {
            at = imagePoint(c, seenAtHeight(0.15), 0.0);
        } else {
            at = imagePoint(c, seenAtHeight(0.425), what == "cyan" ? 0.0 : -M_PI / 2);
            side = 3;
        }
        const double share = classShare(frame, ColorLut(c.colors), at, side, expected);
        QVERIFY2(share >= 90.0, qPrintable(QString("%1 %: %2 at (%3, %4)").arg(share).arg(what).arg(at.x).arg(at.y)));
    }

    // Thesis 4.4: in the ball's square >= 85 % non-green and >= 50 % non-black, for every ball.
    void everyBallPassesColourValidation_data()
    {
        QTest::addColumn<BallKind>("kind");
        QTest::addColumn<double>("distance");
        QTest::addColumn<double>("spin");
        for (BallKind k : kAllBallKinds)
            for (double d : {0.8, 1.5, 2.5, 3.5})
                for (double spin : {0.0, 1.3, 4.0})
                    QTest::newRow(qPrintable(QString("%1, %2 m, spin %3").arg(ballKindName(k).data()).arg(d).arg(spin)))
                        << k << d << spin;
    }
    void everyBallPassesColourValidation()
    {
        QFETCH(BallKind, kind);
        QFETCH(double, distance);
        QFETCH(double, spin);
        const Config c;
        SceneOptions s = openCarpet(distance);
        s.ball = kind;
        s.ballSpin = spin;
        GroundTruth t;
        const cv::Mat frame = SceneSimulator(c).render(s, &t);
        // The pixels whose centres lie in the square of side 1.5 radius around the true centre
        // (BallModelOptions::squareRatio 0.75 of the diameter).
        const ColorLut lut(c.colors);
        const double half = 0.75 * t.radiusPx;
        int green = 0, black = 0, total = 0;
        for (int y = int(std::ceil(t.py - half)); y <= int(std::floor(t.py + half)); ++y)
            for (int x = int(std::ceil(t.px - half)); x <= int(std::floor(t.px + half)); ++x) {
                const cv::Vec3b p = frame.at<cv::Vec3b>(y, x);
                const ColorClass cls = lut.classifyBgr(p[0], p[1], p[2]);
                green += cls == ColorClass::Green;
                black += cls == ColorClass::Black;
                ++total;
            }
        QVERIFY(total >= 9);
        const double nonGreen = 100.0 * (total - green) / total;
        const double nonBlack = 100.0 * (total - black) / total;
        QVERIFY2(nonGreen >= 85.0, qPrintable(QString("non-green %1 % of %2 px").arg(nonGreen).arg(total)));
        QVERIFY2(nonBlack >= 50.0, qPrintable(QString("non-black %1 % of %2 px").arg(nonBlack).arg(total)));
    }

    void occlusionHidesItsShare_data()
    {
        QTest::addColumn<double>("occlusion");
        QTest::newRow("none") << 0.0;
        QTest::newRow("a quarter") << 0.25;
        QTest::newRow("most") << 0.7;
        QTest::newRow("all") << 1.0;
    }
    void occlusionHidesItsShare()
    {
        QFETCH(double, occlusion);
        const Config c;
        SceneOptions s = openCarpet(1.2);
        s.occlusion = occlusion;
        GroundTruth t;
        SceneSimulator(c).render(s, &t);
        QVERIFY2(std::abs(t.visibleFraction - (1 - occlusion)) < 0.05, qPrintable(QString::number(t.visibleFraction)));
        QCOMPARE(t.ballVisible, occlusion <= 0.5);
    }

    // Masked pixels show the robot's structure and hide the ball behind them.
    void maskHidesTheBall()
    {
        Config c;
        SceneOptions s = openCarpet(1.5);
        const GroundTruth free = SceneSimulator(c).groundTruth(s);
        c.mask = cv::Mat(c.geometry.imageHeight, c.geometry.imageWidth, CV_8UC1, cv::Scalar(255));
        const int rodX = int(std::lround(free.px));
        c.mask.colRange(rodX - 2, rodX + 3).setTo(0);  // a support rod through the ball
        GroundTruth t;
        const cv::Mat frame = SceneSimulator(c).render(s, &t);
        QVERIFY(t.visibleFraction < 0.9 && t.visibleFraction > 0.2);
        const cv::Vec3b rod = frame.at<cv::Vec3b>(int(free.py), rodX);
        QVERIFY2(rod[0] < 70 && rod[1] < 70 && rod[2] < 70, "the rod is dark");

        c.mask = cv::Mat(10, 10, CV_8UC1, cv::Scalar(255));
        QVERIFY_EXCEPTION_THROWN(SceneSimulator{c}, std::invalid_argument);
    }

    void ballKindNamesRoundTrip()
    {
        for (std::size_t i = 0; i < kAllBallKinds.size(); ++i) {
            const BallKind k = kAllBallKinds[i];
            QCOMPARE(parseBallKind(ballKindName(k)), std::optional<BallKind>(k));
            QCOMPARE(parseBallKind(std::to_string(i + 1)), std::optional<BallKind>(k));  // thesis ball number
        }
        QCOMPARE(ballKindName(BallKind::WhiteBlackGreen), std::string_view("white-black-green"));
        QVERIFY(!parseBallKind("purple"));
        QVERIFY(!parseBallKind(""));
        QVERIFY(!parseBallKind("6"));
    }

    void tourIsDeterministicAndKeepsTheBallInRange_data()
    {
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<double>("ballX");
        QTest::addColumn<double>("ballY");
        QTest::newRow("thesis spot, seed 1") << 1u << -0.05 << 2.0;
        QTest::newRow("thesis spot, seed 7") << 7u << -0.05 << 2.0;
        QTest::newRow("other half") << 3u << 3.0 << -1.5;
    }
    void tourIsDeterministicAndKeepsTheBallInRange()
    {
        QFETCH(unsigned, seed);
        QFETCH(double, ballX);
        QFETCH(double, ballY);
        TourOptions o;
        o.seed = seed;
        o.ballX = ballX;
        o.ballY = ballY;
        o.shadow = o.feet = true;
        const std::vector<SceneOptions> a = makeTour(o);
        const std::vector<SceneOptions> b = makeTour(o);
        QCOMPARE(int(a.size()), o.frames);
        const Config c;
        const SceneSimulator sim(c);
        int visible = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            const SceneOptions& s = a[i];
            QCOMPARE(s.robot.x, b[i].robot.x);
            QCOMPARE(s.robot.y, b[i].robot.y);
            QCOMPARE(s.robot.heading, b[i].robot.heading);
            QCOMPARE(s.seed, b[i].seed);
            QCOMPARE(s.obstacles.size(), b[i].obstacles.size());
            QVERIFY(s.humanFeet && s.headShadow);
            QCOMPARE(s.ballX, ballX);
            QCOMPARE(s.ballY, ballY);
            const double d = std::hypot(s.ballX - s.robot.x, s.ballY - s.robot.y);
            QVERIFY2(d >= 0.6 && d <= 4.0, qPrintable(QString("frame %1: ball %2 m away").arg(i).arg(d)));
            for (const ObstacleRobot& r : s.obstacles)
                QVERIFY2(std::hypot(r.x - s.robot.x, r.y - s.robot.y) > r.radius + 0.5, "drives into a robot");
            if (i > 0) {  // smooth: small steps in position and heading
                QVERIFY(std::hypot(s.robot.x - a[i - 1].robot.x, s.robot.y - a[i - 1].robot.y) < 0.2);
                QVERIFY(std::abs(std::remainder(s.robot.heading - a[i - 1].robot.heading, 2 * M_PI)) < 0.2);
            }
            visible += sim.groundTruth(s).ballVisible;
        }
        QCOMPARE(visible, o.frames);
        // Frame 0 stands on waypoint 1; frames differ in noise seed.
        const cv::Point2d first = tourWaypoints(o)[0];
        QVERIFY(std::hypot(a[0].robot.x - first.x, a[0].robot.y - first.y) < 1e-9);
        QVERIFY(a[0].seed != a[1].seed);
        o.seed = seed + 1;
        const std::vector<SceneOptions> other = makeTour(o);
        QVERIFY(other[0].obstacles[0].x != a[0].obstacles[0].x);
    }
};

QTEST_GUILESS_MAIN(SceneSimulatorTest)
#include "calib_scene_test.moc"
