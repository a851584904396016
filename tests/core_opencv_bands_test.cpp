// opencv_hough.band_radius_span: cv::HoughCircles per distance ring, each with the ball's own
// radius range there, so a small far ball is not outranked by the larger circles nearer the robot.
#include "DrawnScene.h"
#include "core/OpenCvHough.h"
#include "core/OpenCvRadiusBands.h"
#include "core/Pipeline.h"

#include <QtTest>

#include <cmath>

using namespace omnitune;
using namespace omnitune::test;

namespace {

// A far ball (200 px, ~4.5 px radius) and, nearer the robot, ten black discs of the ball's size
// there (plausible circles that validation refuses as black), each with more edge than the ball.
cv::Mat farBallBehindClutter(const Config& c, cv::Point& ball)
{
    cv::Mat frame = greenField(c);
    for (int i = 0; i < 10; ++i) drawBall(frame, c, 95 + 8 * i, 20 + 34 * i, kBlack);
    ball = drawBall(frame, c, 200, 200);
    return frame;
}

}  // namespace

class OpenCvBandsTest : public QObject {
    Q_OBJECT
private slots:
    void ringsCoverTheProcessedAreaWithinTheSpan()
    {
        Config c;
        const Geometry geometry(c.geometry, cv::Mat());
        const BallModel ball(c.ball);
        std::vector<OpenCvRadiusBand> bands;
        openCvRadiusBands(geometry, ball, c.opencvHough, bands);
        QVERIFY(bands.size() >= 3);
        QCOMPARE(bands.front().minDistancePx, c.geometry.innerRadius);
        QVERIFY(bands.back().maxDistancePx > c.geometry.outerRadius);
        for (std::size_t i = 0; i < bands.size(); ++i) {
            const OpenCvRadiusBand& b = bands[i];
            if (i > 0) QCOMPARE(b.minDistancePx, bands[i - 1].maxDistancePx);  // no gap, no overlap
            const double rNear = ball.radiusAt(b.minDistancePx);
            const double rFar = ball.radiusAt(std::min(b.maxDistancePx - 1.0, c.geometry.outerRadius));
            QVERIFY2(std::max(rNear, rFar) <= std::min(rNear, rFar) * c.opencvHough.bandRadiusSpan + 1e-9,
                     qPrintable(QString("ring %1: %2..%3 px").arg(i).arg(rNear).arg(rFar)));
            // The radius range searched holds the ball's radius anywhere in the ring.
            QVERIFY(b.minRadius <= std::min(rNear, rFar) && b.maxRadius >= std::max(rNear, rFar));
            QVERIFY(!b.roi.empty());
        }
        const int rings = int(bands.size());
        c.opencvHough.bandRadiusSpan = 2.0;
        openCvRadiusBands(geometry, ball, c.opencvHough, bands);
        QVERIFY(int(bands.size()) < rings);  // a wider span: fewer rings
        c.opencvHough.bandRadiusSpan = 0;  // thesis: one search
        openCvRadiusBands(geometry, ball, c.opencvHough, bands);
        QVERIFY(bands.empty());
    }

    void farBallIsFoundBesideStrongerCircles()
    {
        Config c;
        c.algorithm = Algorithm::OpenCv;
        cv::Point ball;
        const cv::Mat frame = farBallBehindClutter(c, ball);
        PipelineResult r;
        Pipeline(c).process(frame, PixelFormat::Bgr8, r);
        QVERIFY(r.detection.found);
        QVERIFY(std::hypot(r.detection.px - ball.x, r.detection.py - ball.y) <= 2.0);

        c.opencvHough.bandRadiusSpan = 0;  // one search: the discs use up max_circles
        Pipeline(c).process(frame, PixelFormat::Bgr8, r);
        QVERIFY(!r.detection.found);
    }

    void emptyCarpetGivesNoPlausibleCircle()
    {
        Config c;
        const EdgeStages s(c, greenField(c));
        OpenCvHough hough;
        std::vector<BallCandidate> cands;
        hough.process(s.binary, c.opencvHough, s.geometry, s.ball, cands);
        QVERIFY(cands.empty());
    }
};

QTEST_GUILESS_MAIN(OpenCvBandsTest)
#include "core_opencv_bands_test.moc"
