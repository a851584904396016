// calib/fit/BallSquashFit: the ball's radial squash from a distance map, checked on two mirror
// mappings whose squash is known in closed form, and the calibration writing it into the config.
#include "calib/fit/BallSquashFit.h"
#include "core/BallModel.h"

#include <QtTest>

#include <cmath>
#include <functional>

using namespace omnitune;

namespace {

constexpr double kHeight = 0.7;  // m, viewpoint above the ground
constexpr double kFocal = 140.0; // px per radian (equidistant) or the stereographic scale

// A distance map table for a mirror mapping alpha (from the downward axis) to image radius.
DistanceMapOptions mapOf(const std::function<double(double)>& rhoOfAlpha)
{
    DistanceMapOptions m;
    m.viewpointHeight = kHeight;
    m.pixelRadii.clear();
    m.groundDistances.clear();
    for (double alpha = 0.0; alpha < 1.45; alpha += 0.02) {
        m.pixelRadii.push_back(rhoOfAlpha(alpha));
        m.groundDistances.push_back(kHeight * std::tan(alpha));
    }
    return m;
}

}  // namespace

class FitSquashTest : public QObject {
    Q_OBJECT
private slots:
    // Stereographic projection is conformal: a small sphere stays round (squash 1).
    void conformalMirrorKeepsTheBallRound()
    {
        const DistanceMapOptions map = mapOf([](double a) { return 2.0 * kFocal * std::tan(a / 2.0); });
        const auto k = fitBallSquash(map, 60, 200);
        QVERIFY(k);
        BallModelOptions o;
        o.squashC0 = (*k)[0];
        o.squashC1 = (*k)[1];
        o.squashC2 = (*k)[2];
        const BallModel ball(o);
        for (double d : {70.0, 130.0, 190.0}) QVERIFY2(std::abs(ball.squashAt(d) - 1.0) < 0.03, qPrintable(QString::number(ball.squashAt(d))));
    }

    // Equidistant (rho = f alpha): radial px per radian f, tangential rho / sin(alpha), so the
    // squash is sin(alpha) / alpha, falling towards the rim.
    void equidistantMirrorSquashesTheFarBall()
    {
        const DistanceMapOptions map = mapOf([](double a) { return kFocal * a; });
        const auto k = fitBallSquash(map, 40, 200);
        QVERIFY(k);
        BallModelOptions o;
        o.squashC0 = (*k)[0];
        o.squashC1 = (*k)[1];
        o.squashC2 = (*k)[2];
        const BallModel ball(o);
        for (double d : {60.0, 120.0, 190.0}) {
            const double alpha = d / kFocal;
            const double want = std::sin(alpha) / alpha;
            QVERIFY2(std::abs(ball.squashAt(d) - want) < 0.03,
                     qPrintable(QString("%1 px: %2, want %3").arg(d).arg(ball.squashAt(d)).arg(want)));
        }
        QVERIFY(ball.squashAt(190) < ball.squashAt(60) - 0.2);
    }

    void noRingNoSquash()
    {
        const DistanceMapOptions map = mapOf([](double a) { return kFocal * a; });
        QVERIFY(!fitBallSquash(map, 100, 101));
        DistanceMapOptions flat = map;
        flat.viewpointHeight = 0;
        QVERIFY(!fitBallSquash(flat, 40, 200));
    }

    void modelWithoutSquashIsRound()
    {
        const BallModel ball;
        QCOMPARE(ball.squashAt(150), 1.0);
        BallModelOptions negative;
        negative.squashC0 = -0.5;  // nonsense far outside the fitted ring: no squash, not a flip
        QCOMPARE(BallModel(negative).squashAt(150), 1.0);
    }
};

QTEST_GUILESS_MAIN(FitSquashTest)
#include "calib_fit_squash_test.moc"
