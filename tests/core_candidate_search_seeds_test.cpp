// Blob seeds of a radially squashed ball (hough.seeds_squashed): a far ball in a spherical
// mirror is an ellipse wider than a circle of its area-equivalent radius. Its blob has the
// ball's area but a box longer than that circle's diameter; with the squash-aware box it is
// still seeded, and a line piece of the same area is still not.
#include "DrawnScene.h"
#include "core/BallModel.h"
#include "core/BlobSeeds.h"
#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <cmath>

using namespace omnitune;
using namespace omnitune::test;

namespace {

constexpr double kSquash = 0.5;  // radial over tangential semi-axis, as near a spherical mirror's rim

// A binary image (255 green) with a non-green ellipse of the model's area at `distance`, its
// short axis along the ray; returns its centre.
cv::Point drawSquashedBall(cv::Mat& binary, const Config& c, const BallModel& ball, double distance, double angleDeg)
{
    const cv::Point2d p = pointAt(c, distance, angleDeg);
    const double r = ball.radiusAt(distance);
    const double tangential = r / std::sqrt(kSquash);
    const double radial = r * std::sqrt(kSquash);
    cv::ellipse(binary, cv::Point(cvRound(p.x), cvRound(p.y)), cv::Size(cvRound(radial), cvRound(tangential)),
                angleDeg, 0, 360, cv::Scalar(0), cv::FILLED);
    return cv::Point(cvRound(p.x), cvRound(p.y));
}

}  // namespace

class CandidateSearchSeedsTest : public QObject {
    Q_OBJECT
private slots:
    void squashedBallIsSeeded()
    {
        Config c;
        c.ball.squashC0 = kSquash;
        const BallModel ball(c.ball);
        const Geometry geometry(c.geometry, cv::Mat());
        cv::Mat binary(geometry.imageSize(), CV_8UC1, cv::Scalar(255));
        const cv::Point centre = drawSquashedBall(binary, c, ball, 200, 0);

        BlobSeeds seeds;
        QVERIFY(seeds.find(binary, geometry, ball, 4, false).empty());  // the round box refuses it
        const auto& found = seeds.find(binary, geometry, ball, 4, true);
        QCOMPARE(int(found.size()), 1);
        QVERIFY(std::hypot(found[0].x - centre.x, found[0].y - centre.y) <= 1.5);
    }

    void linePieceIsNotSeeded()
    {
        Config c;
        c.ball.squashC0 = kSquash;
        const BallModel ball(c.ball);
        const Geometry geometry(c.geometry, cv::Mat());
        cv::Mat binary(geometry.imageSize(), CV_8UC1, cv::Scalar(255));
        // The ball's area as a 3 px wide piece of line across the ray: longer than the tangential axis.
        const double r = ball.radiusAt(200);
        const double length = M_PI * r * r / 3.0;
        const cv::Point2d a = pointAt(c, 200, -length / 2.0 / 200.0 * 180.0 / M_PI);
        const cv::Point2d b = pointAt(c, 200, length / 2.0 / 200.0 * 180.0 / M_PI);
        QVERIFY(length > 2.0 * r / std::sqrt(kSquash) + 2.0);
        cv::line(binary, cv::Point(cvRound(a.x), cvRound(a.y)), cv::Point(cvRound(b.x), cvRound(b.y)), cv::Scalar(0), 3);
        BlobSeeds seeds;
        QVERIFY(seeds.find(binary, geometry, ball, 4, true).empty());
    }
};

QTEST_GUILESS_MAIN(CandidateSearchSeedsTest)
#include "core_candidate_search_seeds_test.moc"
