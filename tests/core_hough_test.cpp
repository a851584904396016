// The specific circular Hough transform (thesis 4.1) and the cv::HoughCircles path (4.2).
#include "DrawnScene.h"
#include "core/ConfigSchema.h"
#include "core/OpenCvHough.h"
#include "core/SpecificHough.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {
double dist(const BallCandidate& c, cv::Point p) { return std::hypot(c.x - p.x, c.y - p.y); }
}  // namespace

class HoughTest : public QObject {
    Q_OBJECT
private slots:
    void maximumAtTheDrawnBall_data()
    {
        QTest::addColumn<double>("distance");
        QTest::addColumn<double>("angle");
        QTest::newRow("area 2, 80 px") << 80.0 << 10.0;
        QTest::newRow("area 3, 120 px") << 120.0 << 100.0;
        QTest::newRow("area 4, 155 px") << 155.0 << 200.0;
        QTest::newRow("area 5, 190 px") << 190.0 << 290.0;
        QTest::newRow("area 6, 225 px") << 225.0 << 45.0;
    }
    void maximumAtTheDrawnBall()
    {
        QFETCH(double, distance);
        QFETCH(double, angle);
        Config c;
        c.hough.multipleMaxima = false;
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, distance, angle);
        const EdgeStages s(c, frame);
        SpecificHough hough(c.hough, s.geometry, s.ball);
        std::vector<BallCandidate> cands;
        hough.process(s.edges, s.binary, cands);
        QCOMPARE(int(cands.size()), 1);
        QVERIFY2(dist(cands[0], ball) <= 1.0,
                 qPrintable(QString("maximum at (%1,%2), ball at (%3,%4)").arg(cands[0].x).arg(cands[0].y).arg(ball.x).arg(ball.y)));
        QVERIFY(std::abs(cands[0].expectedRadiusPx - expectedRadius(c, cands[0].distancePx)) < 1e-9);
    }

    void eachRadialAreaHasItsOwnMaximum()
    {
        const Config c;
        cv::Mat frame = greenField(c);
        // One ball in each of areas 2..6 (area 1, 0..70 px, is mostly the robot body here).
        const double distances[] = {88, 123, 155, 188, 223};
        std::vector<cv::Point> balls;
        for (int i = 0; i < 5; ++i) balls.push_back(drawBall(frame, c, distances[i], 72.0 * i));
        const EdgeStages s(c, frame);
        SpecificHough hough(c.hough, s.geometry, s.ball);
        std::vector<BallCandidate> cands;
        hough.process(s.edges, s.binary, cands);
        for (int i = 0; i < 5; ++i) {
            const auto it = std::find_if(cands.begin(), cands.end(), [&](const BallCandidate& k) { return k.area == i + 1; });
            QVERIFY2(it != cands.end(), qPrintable(QString("no candidate in area %1").arg(i + 2)));
            QVERIFY2(dist(*it, balls[std::size_t(i)]) <= 1.0, qPrintable(QString("area %1 maximum off").arg(i + 2)));
        }
    }

    void singleMaximumModeGivesOneCandidate()
    {
        Config c;
        c.hough.multipleMaxima = false;
        c.hough.blobSeeds = false;  // the maxima alone (each ball is also a blob seed)
        cv::Mat frame = greenField(c);
        drawBall(frame, c, 100, 0);
        drawBall(frame, c, 200, 180);
        const EdgeStages s(c, frame);
        SpecificHough hough(c.hough, s.geometry, s.ball);
        std::vector<BallCandidate> cands;
        hough.process(s.edges, s.binary, cands);
        QCOMPARE(int(cands.size()), 1);
    }

    void noVotesOnGreenOrOutsideTheRing()
    {
        const Config c;
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 150, 60);
        const EdgeStages s(c, frame);
        SpecificHough hough(c.hough, s.geometry, s.ball);
        std::vector<BallCandidate> cands;
        hough.process(s.edges, s.binary, cands);
        const cv::Mat& acc = hough.accumulator();
        QVERIFY(acc.at<quint16>(ball) > 0);
        for (int y = 0; y < acc.rows; ++y)
            for (int x = 0; x < acc.cols; ++x)
                if (acc.at<quint16>(y, x) > 0) {
                    QVERIFY(s.binary.at<uchar>(y, x) == 0);  // non-green and processed
                    QVERIFY(s.geometry.isUsed(x, y));
                }
    }

    void votesNearTheRobotCountTwice()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 66, 0);
        const EdgeStages s(c, frame);
        SpecificHough doubled(c.hough, s.geometry, s.ball);
        c.hough.nearRobotWeight = 1;
        SpecificHough single(c.hough, s.geometry, s.ball);
        std::vector<BallCandidate> cands;
        doubled.process(s.edges, s.binary, cands);
        single.process(s.edges, s.binary, cands);
        const int a = doubled.accumulator().at<quint16>(ball);
        const int b = single.accumulator().at<quint16>(ball);
        QVERIFY(b > 0);
        QCOMPARE(a, 2 * b);
    }

    void openCvFindsTheBall()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 110, 135);
        const EdgeStages s(c, frame);
        OpenCvHough hough;
        std::vector<BallCandidate> cands;
        hough.process(s.binary, c.opencvHough, s.geometry, s.ball, cands);
        QCOMPARE(int(cands.size()), 1);
        QVERIFY(dist(cands[0], ball) <= 2.0);
        QCOMPARE(cands[0].rejected, RejectReason::None);
        QCOMPARE(cands[0].source, CandidateSource::OpenCvHough);
    }

    void openCvRejectsATooLargeCircle()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const double d = 200;
        const cv::Point centre = pointAt(c, d, 300);
        cv::circle(frame, centre, int(3 * expectedRadius(c, d)), kOrange, cv::FILLED);
        const EdgeStages s(c, frame);
        OpenCvHough hough;
        std::vector<BallCandidate> cands;
        c.opencvHough.bandRadiusSpan = 0;  // the one search; per ring that radius is never searched
        hough.process(s.binary, c.opencvHough, s.geometry, s.ball, cands);
        QCOMPARE(int(cands.size()), 1);
        QCOMPARE(cands[0].rejected, RejectReason::RadiusTooLarge);
        c.opencvHough.bandRadiusSpan = 1.25;
        cands.clear();
        hough.process(s.binary, c.opencvHough, s.geometry, s.ball, cands);
        for (const BallCandidate& k : cands) QVERIFY(k.rejected != RejectReason::None);
    }

    // Bad bounds are a user error reported once, by checkConfig() with the key; the stage only
    // asserts what its one-byte area index needs.
    void rejectsBadAreaBounds()
    {
        Config c;
        c.hough.areaBounds = {70, 60, 140};
        const auto issues = checkConfig(c);
        QVERIFY(!issues.empty());
        QCOMPARE(QString::fromStdString(issues.front().key), QString("hough.area_bounds"));
        c.hough.areaBounds.clear();
        const Geometry g(c.geometry, cv::Mat());
        const BallModel b(c.ball);
        QVERIFY_EXCEPTION_THROWN(SpecificHough(c.hough, g, b), cv::Exception);
    }
};

QTEST_GUILESS_MAIN(HoughTest)
#include "core_hough_test.moc"
