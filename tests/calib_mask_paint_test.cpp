// The mask editor's pixel work (calib/mask/MaskPaint): exactly which pixels a brush stroke, a
// polygon and a flood fill change, checked against hand counts and against OpenCV's own
// point-in-polygon test.
#include "calib/mask/MaskPaint.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

namespace {

cv::Mat processed(int w = 20, int h = 20) { return cv::Mat(h, w, CV_8UC1, cv::Scalar(kMaskProcessed)); }

int robotPixels(const cv::Mat& m) { return m.rows * m.cols - cv::countNonZero(m); }

}  // namespace

class MaskPaintTest : public QObject {
    Q_OBJECT
private slots:
    void stroke_data()
    {
        QTest::addColumn<QPointF>("a");
        QTest::addColumn<QPointF>("b");
        QTest::addColumn<double>("radius");
        QTest::addColumn<int>("changed");
        // Pixel (5, 5) has its centre at (5.5, 5.5).
        QTest::newRow("dot r0: the pixel under it") << QPointF(5.5, 5.5) << QPointF(5.5, 5.5) << 0.0 << 1;
        QTest::newRow("dot r1: a plus (distance 1 counts)") << QPointF(5.5, 5.5) << QPointF(5.5, 5.5) << 1.0 << 5;
        QTest::newRow("dot r1.5: 3x3") << QPointF(5.5, 5.5) << QPointF(5.5, 5.5) << 1.5 << 9;
        QTest::newRow("line r0.5: one row of 7") << QPointF(2.5, 5.5) << QPointF(8.5, 5.5) << 0.5 << 7;
        QTest::newRow("line r1: 3 rows of 7 and the round ends") << QPointF(2.5, 5.5) << QPointF(8.5, 5.5) << 1.0 << 23;
        QTest::newRow("corner dot: the image clips it") << QPointF(0.5, 0.5) << QPointF(0.5, 0.5) << 1.5 << 4;
        QTest::newRow("off the image") << QPointF(-10, -10) << QPointF(-5, -20) << 2.0 << 0;
    }
    void stroke()
    {
        QFETCH(QPointF, a);
        QFETCH(QPointF, b);
        QFETCH(double, radius);
        QFETCH(int, changed);
        cv::Mat m = processed();
        QCOMPARE(paintStroke(m, {a.x(), a.y()}, {b.x(), b.y()}, radius, kMaskRobot), changed);
        QCOMPARE(robotPixels(m), changed);
        // Painting it again changes nothing; erasing it gives the image back.
        QCOMPARE(paintStroke(m, {a.x(), a.y()}, {b.x(), b.y()}, radius, kMaskRobot), 0);
        QCOMPARE(paintStroke(m, {a.x(), a.y()}, {b.x(), b.y()}, radius, kMaskProcessed), changed);
        QCOMPARE(robotPixels(m), 0);
    }

    void strokeCoversExactlyThePixelsNearTheSegment()
    {
        cv::Mat m = processed(40, 30);
        const cv::Point2d a(3.2, 4.7), b(31.9, 22.1);
        const double r = 2.6;
        paintStroke(m, a, b, r, kMaskRobot);
        for (int y = 0; y < m.rows; ++y)
            for (int x = 0; x < m.cols; ++x) {
                // Distance from the centre to the segment, computed another way: the nearer of
                // the two ends, or the perpendicular when the foot falls between them.
                const cv::Point2d p(x + 0.5, y + 0.5), d = b - a;
                const double along = (p - a).dot(d) / std::sqrt(d.dot(d));
                const double perp = std::abs(d.x * (p.y - a.y) - d.y * (p.x - a.x)) / std::sqrt(d.dot(d));
                const double dist = along < 0 ? cv::norm(p - a) : along > cv::norm(d) ? cv::norm(p - b) : perp;
                if (std::abs(dist - r) < 1e-9) continue;
                QVERIFY2((m.at<std::uint8_t>(y, x) == kMaskRobot) == (dist < r), qPrintable(QString("pixel %1,%2").arg(x).arg(y)));
            }
    }

    void polygonRectangle()
    {
        cv::Mat m = processed();
        // Centres x + 0.5 in [2, 6), y + 0.5 in [2, 5): 4 x 3 pixels.
        QCOMPARE(fillPolygon(m, {{2, 2}, {6, 2}, {6, 5}, {2, 5}}, kMaskRobot), 12);
        QCOMPARE(cv::countNonZero(m(cv::Rect(2, 2, 4, 3))), 0);
        QCOMPARE(robotPixels(m), 12);
        QCOMPARE(fillPolygon(m, {{2, 2}, {6, 2}}, kMaskRobot), 0);  // two vertices: no area
    }

    void polygonAgreesWithOpenCv()
    {
        cv::Mat m = processed(60, 50);
        const std::vector<cv::Point2d> poly{{5.3, 4.1}, {52.7, 9.9}, {30.2, 20.4}, {44.8, 46.3}, {8.6, 38.2}};
        const int changed = fillPolygon(m, poly, kMaskRobot);
        std::vector<cv::Point2f> contour;
        for (const auto& p : poly) contour.emplace_back(float(p.x), float(p.y));
        int inside = 0;
        for (int y = 0; y < m.rows; ++y)
            for (int x = 0; x < m.cols; ++x) {
                const double d = cv::pointPolygonTest(contour, cv::Point2f(x + 0.5f, y + 0.5f), true);
                if (std::abs(d) < 1e-3) continue;  // on the outline: either is right
                inside += d > 0;
                QVERIFY2((m.at<std::uint8_t>(y, x) == kMaskRobot) == (d > 0), qPrintable(QString("pixel %1,%2").arg(x).arg(y)));
            }
        QVERIFY(changed >= inside);
        QVERIFY(inside > 500);
    }

    void polygonSelfCrossingLeavesTheDoublyEnclosedPart()
    {
        // A pentagram: its centre pentagon is enclosed twice (even-odd: outside).
        cv::Mat m = processed(100, 100);
        std::vector<cv::Point2d> star;
        for (int i = 0; i < 5; ++i) {
            const double a = -CV_PI / 2 + i * 4 * CV_PI / 5;
            star.emplace_back(50 + 45 * std::cos(a), 50 + 45 * std::sin(a));
        }
        QVERIFY(fillPolygon(m, star, kMaskRobot) > 0);
        QCOMPARE(int(m.at<std::uint8_t>(50, 50)), int(kMaskProcessed));  // the centre
        QCOMPARE(int(m.at<std::uint8_t>(15, 50)), int(kMaskRobot));      // the top point
    }

    void floodFillsTheRegionAndStopsAtItsBorder()
    {
        cv::Mat m = processed();
        cv::rectangle(m, cv::Rect(4, 4, 10, 10), cv::Scalar(kMaskRobot), 1);  // a closed robot outline
        QCOMPARE(floodFillMask(m, {8.5, 8.5}, kMaskRobot), 64);                  // its 8 x 8 inside
        QCOMPARE(robotPixels(m), 100);
        QCOMPARE(floodFillMask(m, {8.5, 8.5}, kMaskRobot), 0);  // already robot
        // Clearing the robot region gives back the whole image.
        QCOMPARE(floodFillMask(m, {4.2, 4.2}, kMaskProcessed), 100);
        QCOMPARE(robotPixels(m), 0);
        QCOMPARE(floodFillMask(m, {-1, 3}, kMaskRobot), 0);
        QCOMPARE(floodFillMask(m, {3, 20}, kMaskRobot), 0);
    }

    void floodFillIsFourConnected()
    {
        // A diagonal line of robot pixels separates the two halves for a 4-connected fill.
        cv::Mat m = processed(10, 10);
        for (int i = 0; i < 10; ++i) m.at<std::uint8_t>(i, i) = kMaskRobot;
        QCOMPARE(floodFillMask(m, {8.5, 1.5}, kMaskRobot), 45);  // the upper-right triangle only
        QCOMPARE(int(m.at<std::uint8_t>(8, 1)), int(kMaskProcessed));
    }
};

QTEST_GUILESS_MAIN(MaskPaintTest)
#include "calib_mask_paint_test.moc"
