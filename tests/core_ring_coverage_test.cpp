// ringShareInImage: how much of the processed ring lies inside the image, which the config
// check uses to refuse a ring wholly off the image. It must answer for any radius a hand-edited
// (or fuzzed) config holds: a huge outer radius once overflowed its step count.
#include "core/RingCoverage.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace omnitune;

class RingCoverageTest : public QObject {
    Q_OBJECT
private slots:
    void ringInsideTheImageIsWhollyIn()
    {
        GeometryOptions g;  // 640x480, centre (320, 240), radii 50..200
        g.outerRadius = 200.0;
        QVERIFY(std::abs(ringShareInImage(g) - 1.0) < 1e-3);
    }

    void ringCentredOnACornerIsAQuarterIn()
    {
        GeometryOptions g;
        g.centerX = 0.0;
        g.centerY = 0.0;
        g.innerRadius = 50.0;
        g.outerRadius = 200.0;
        QVERIFY(std::abs(ringShareInImage(g) - 0.25) < 5e-3);
    }

    void ringOffTheImageIsNotIn()
    {
        GeometryOptions g;
        g.centerX = 2000.0;
        g.centerY = 2000.0;
        QCOMPARE(ringShareInImage(g), 0.0);
    }

    void hugeOrNonFiniteRadiiGiveAShareNotAnOverflow()
    {
        GeometryOptions g;
        g.outerRadius = 1e300;  // area overflows to infinity: no share to speak of
        QCOMPARE(ringShareInImage(g), 0.0);
        g.outerRadius = 1e12;   // the image is a vanishing part of such a ring
        const double share = ringShareInImage(g);
        QVERIFY(share >= 0.0 && share < 1e-6);
        g.outerRadius = std::numeric_limits<double>::infinity();
        QCOMPARE(ringShareInImage(g), 0.0);
        g.outerRadius = 240.0;
        g.centerY = std::numeric_limits<double>::quiet_NaN();
        QCOMPARE(ringShareInImage(g), 0.0);
    }
};

QTEST_GUILESS_MAIN(RingCoverageTest)
#include "core_ring_coverage_test.moc"
