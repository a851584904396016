// The binary (green / non-green) image and the Canny edge detector.
#include "DrawnScene.h"
#include "core/ConfigSchema.h"
#include "core/RoundHalfAway.h"
#include "core/SpeckFreeEdges.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

class EdgesTest : public QObject {
    Q_OBJECT
private slots:
    void binaryIsGreenWhiteElseBlack()
    {
        const Config c;
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 150, 30);
        cv::line(frame, pointAt(c, 100, 200), pointAt(c, 200, 200), kWhite, 4);
        const EdgeStages s(c, frame);
        QCOMPARE(int(s.binary.at<uchar>(ball)), 0);                        // ball: non-green
        QCOMPARE(int(s.binary.at<uchar>(pointAt(c, 150, 200))), 0);        // line: non-green
        QCOMPARE(int(s.binary.at<uchar>(pointAt(c, 150, 100))), 255);      // carpet
        QCOMPARE(int(s.binary.at<uchar>(int(c.geometry.centerY), int(c.geometry.centerX))), 255);  // robot: unused
        QCOMPARE(int(s.binary.at<uchar>(0, 0)), 255);                      // outside the mirror
    }

    // A ball touching a line: with the thesis' binary image they are one non-green blob and no
    // edge runs between them; with white at its own level an edge does.
    void whiteLevelPutsAnEdgeBetweenBallAndLine()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const double r = expectedRadius(c, 150);
        const cv::Point ball = drawBall(frame, c, 150, 0);
        // A vertical line whose left side touches the ball's right side.
        const int lineX = ball.x + int(std::lround(r)) + 3;
        cv::rectangle(frame, cv::Point(lineX - 3, ball.y - 40), cv::Point(lineX + 3, ball.y + 40), kWhite, cv::FILLED);
        const cv::Rect between(lineX - 4, ball.y - 2, 2, 5);  // the ball/line border around the ball's right end
        {
            const EdgeStages s(c, frame);
            QCOMPARE(int(s.binary.at<uchar>(ball.y, lineX)), 0);
            QCOMPARE(cv::countNonZero(s.edges(between)), 0);
            QCOMPARE(s.frontEnd.edgeSource(s.binary).data, s.binary.data);
        }
        c.edges.whiteLevel = 128;
        QVERIFY(checkConfig(c).empty());
        const EdgeStages s(c, frame);
        QCOMPARE(int(s.binary.at<uchar>(ball.y, lineX)), 128);
        QCOMPARE(int(s.binary.at<uchar>(ball)), 0);
        QVERIFY(cv::countNonZero(s.edges(between)) > 0);
        // The line's other side, against the carpet, keeps its edge.
        QVERIFY(cv::countNonZero(s.edges(cv::Rect(lineX + 2, ball.y - 2, 3, 5))) > 0);
        // Other levels are rounded down to a multiple of 16, which keeps the Hough's centre test.
        c.edges.whiteLevel = 100;
        QCOMPARE(int(EdgeStages(c, frame).binary.at<uchar>(ball.y, lineX)), 96);
    }

    // edges.drop_specks: a one-pixel speck on the carpet (dim light's black freckles) makes a ring
    // of edges with the thesis' thresholds and none with the switch on; a ball's border and a
    // 3x3 px blob's stay as they were. (A 2x2 speck has no edges either way: its four pixels tie
    // in the non-maximum suppression.)
    void dropSpecksRemovesSpeckRingsAndKeepsBorders()
    {
        Config c;
        QVERIFY(c.edges.dropSpecks);
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 150, 30);
        auto blob = [&](double angleDeg, int side) {
            const cv::Point p(pointAt(c, 160, angleDeg));
            cv::rectangle(frame, p, p + cv::Point(side - 1, side - 1), kBlack, cv::FILLED);
            return cv::Rect(p.x - 2, p.y - 2, side + 4, side + 4);
        };
        const cv::Rect speck = blob(200, 1);
        const cv::Rect small = blob(300, 3);
        const int r = int(std::ceil(expectedRadius(c, 150))) + 3;
        const cv::Rect aroundBall(ball.x - r, ball.y - r, 2 * r + 1, 2 * r + 1);

        const EdgeStages on(c, frame);
        c.edges.dropSpecks = false;
        const EdgeStages off(c, frame);
        QVERIFY(cv::countNonZero(off.edges(speck)) > 0);
        QCOMPARE(cv::countNonZero(on.edges(speck)), 0);
        for (const cv::Rect& border : {aroundBall, small}) {
            QVERIFY(cv::countNonZero(on.edges(border)) > 0);
            QCOMPARE(cv::countNonZero(on.edges(border) != off.edges(border)), 0);
        }
    }

    // The raised thresholds follow the binary image's smallest step and never lower a setting.
    void speckFreeThresholdsFollowTheSmallestStep()
    {
        EdgeOptions o;
        QCOMPARE(speckFreeCannyOptions(o).cannyLow, 4 * 255 - 1);
        QCOMPARE(speckFreeCannyOptions(o).cannyHigh, 4 * 255 - 1);
        o.whiteLevel = 128;  // steps 128 (white / black) and 127 (green / white)
        QCOMPARE(speckFreeCannyOptions(o).cannyHigh, 4 * 127 - 1);
        o.whiteLevel = 0;
        o.input = EdgeInput::Gray;  // an ordinary Canny on the grayscale: as set
        QCOMPARE(speckFreeCannyOptions(o).cannyHigh, o.cannyHigh);
        o.input = EdgeInput::Binary;
        o.dropSpecks = false;
        QCOMPARE(speckFreeCannyOptions(o).cannyLow, o.cannyLow);
    }

    // opencv_hough.drop_specks: HoughCircles' high threshold follows the same step (its low one is
    // half of it), only on the binary input and never lowered.
    void speckFreeHoughThresholdFollowsTheSmallestStep()
    {
        OpenCvHoughOptions o;
        EdgeOptions e;
        QCOMPARE(speckFreeHoughOptions(o, e).cannyHigh, 4.0 * 255 - 1);
        e.whiteLevel = 128;
        QCOMPARE(speckFreeHoughOptions(o, e).cannyHigh, 4.0 * 127 - 1);
        e.whiteLevel = 0;
        e.input = EdgeInput::Gray;
        QCOMPARE(speckFreeHoughOptions(o, e).cannyHigh, o.cannyHigh);
        e.input = EdgeInput::Binary;
        o.dropSpecks = false;
        QCOMPARE(speckFreeHoughOptions(o, e).cannyHigh, o.cannyHigh);
        o.dropSpecks = true;
        o.cannyHigh = 1020;
        QCOMPARE(speckFreeHoughOptions(o, e).cannyHigh, 1020.0);
    }

    // ... and with it HoughCircles finds on a speckled binary image exactly the circles of the same
    // image without its specks, where canny_high 180 answers the specks with circles of their own.
    void speckFreeHoughCirclesIgnoreSpecks()
    {
        cv::Mat clean(240, 320, CV_8UC1, cv::Scalar(255));
        cv::circle(clean, cv::Point(100, 120), 12, cv::Scalar(0), cv::FILLED);
        cv::circle(clean, cv::Point(220, 90), 8, cv::Scalar(0), cv::FILLED);
        cv::Mat speckled = clean.clone();
        cv::RNG rng{3};
        for (int i = 0; i < 400; ++i) {
            const cv::Point p(rng.uniform(2, 318), rng.uniform(2, 238));
            if (cv::norm(p - cv::Point(100, 120)) > 16 && cv::norm(p - cv::Point(220, 90)) > 12) speckled.at<uchar>(p) = 0;
        }
        const OpenCvHoughOptions o = speckFreeHoughOptions(OpenCvHoughOptions{}, EdgeOptions{});
        auto circles = [&](const cv::Mat& img, double cannyHigh) {
            std::vector<cv::Vec3f> out;
            cv::HoughCircles(img, out, cv::HOUGH_GRADIENT, 1, 6, cannyHigh, 8, 3, 16);
            return out;
        };
        const std::vector<cv::Vec3f> reference = circles(clean, o.cannyHigh);
        QCOMPARE(int(reference.size()), 2);
        QVERIFY(circles(speckled, o.cannyHigh) == reference);
        QVERIFY(circles(speckled, OpenCvHoughOptions{}.cannyHigh).size() > reference.size());
    }

    // edges.input: gray finds the ball on a frame whose colours match no class (no segmentation).
    void grayInputGivesEdgesWithoutSegmentation()
    {
        Config c;
        cv::Mat frame(c.geometry.imageHeight, c.geometry.imageWidth, CV_8UC3, cv::Scalar(90, 90, 90));  // grey floor
        const cv::Point ball = drawBall(frame, c, 150, 60, cv::Scalar(200, 200, 200));  // light grey ball
        const double r = expectedRadius(c, 150);
        const cv::Rect rim(ball.x - int(r) - 2, ball.y - int(r) - 2, 2 * int(r) + 5, 2 * int(r) + 5);
        {
            const EdgeStages s(c, frame);  // binary: no green anywhere, no edge at the ball
            QCOMPARE(cv::countNonZero(s.edges(rim)), 0);
        }
        c.edges.input = EdgeInput::Gray;
        const EdgeStages s(c, frame);
        QVERIFY(cv::countNonZero(s.edges(rim)) > 4 * r);  // roughly the circumference
        const cv::Mat& gray = s.frontEnd.edgeSource(s.binary);
        QVERIFY(gray.data != s.binary.data);
        QVERIFY(std::abs(int(gray.at<uchar>(ball)) - 200) <= 1);
        QVERIFY(std::abs(int(gray.at<uchar>(pointAt(c, 100, 200))) - 90) <= 1);
        QCOMPARE(cv::countNonZero(s.edges & ~s.geometry.edgeMask()), 0);  // still only inside the ring
    }

    // Our allocation-free Canny must give exactly OpenCV's result (3x3 Sobel, L1 norm).
    void cannyMatchesOpenCv_data()
    {
        QTest::addColumn<int>("seed");
        QTest::addColumn<int>("low");
        QTest::addColumn<int>("high");
        QTest::newRow("thesis thresholds, blobs") << 1 << 60 << 180;
        QTest::newRow("thesis thresholds, other blobs") << 2 << 60 << 180;
        QTest::newRow("low thresholds") << 3 << 10 << 30;
        QTest::newRow("high thresholds") << 4 << 300 << 900;
    }
    void cannyMatchesOpenCv()
    {
        QFETCH(int, seed);
        QFETCH(int, low);
        QFETCH(int, high);
        cv::RNG rng{uint64(seed)};
        cv::Mat img(120, 160, CV_8UC1, cv::Scalar(255));
        for (int i = 0; i < 25; ++i)
            cv::circle(img, cv::Point(rng.uniform(0, 160), rng.uniform(0, 120)), rng.uniform(2, 20),
                       cv::Scalar(i % 3 == 0 ? 0 : rng.uniform(0, 256)), cv::FILLED);
        cv::line(img, cv::Point(0, 10), cv::Point(159, 100), cv::Scalar(0), 3);
        cv::Mat ours;
        CannyDetector canny;
        canny.detect(img, EdgeOptions{low, high}, ours);
        cv::Mat reference;
        cv::Canny(img, reference, low, high, 3, false);
        QCOMPARE(cv::countNonZero(ours != reference), 0);
        QVERIFY(cv::countNonZero(ours) > 100);
    }

    // ... also on a noisy grey image of a width that is no multiple of the 16-pixel blocks the
    // non-maximum suppression skips by, and after the detector served another image size.
    void cannyMatchesOpenCvOnNoise()
    {
        cv::Mat img(83, 157, CV_8UC1);
        cv::RNG rng{7};
        rng.fill(img, cv::RNG::UNIFORM, 0, 256);
        cv::GaussianBlur(img, img, cv::Size(3, 3), 0.8);
        cv::rectangle(img, cv::Rect(40, 20, 50, 30), cv::Scalar(255), cv::FILLED);
        CannyDetector canny;
        cv::Mat ours;
        canny.detect(cv::Mat(30, 40, CV_8UC1, cv::Scalar(0)), EdgeOptions{60, 180}, ours);  // another size first
        canny.detect(img, EdgeOptions{60, 180}, ours);
        cv::Mat reference;
        cv::Canny(img, reference, 60, 180, 3, false);
        QCOMPARE(cv::countNonZero(ours != reference), 0);
        QVERIFY(cv::countNonZero(ours) > 500);
    }

    // The validation's pixel walks round with roundHalfAway instead of std::lround: the same
    // integer for halves, near-halves and negative coordinates.
    void roundHalfAwayIsLround()
    {
        const double values[] = {0.0, 0.5, -0.5, 1.5, -1.5, 2.4999999999999996, 0.49999999999999994, -0.49999999999999994,
                                 3.5000000000000004, -7.25, 639.5, -639.5, 1e9 + 0.5};
        for (double v : values) QCOMPARE(roundHalfAway(v), int(std::lround(v)));
        cv::RNG rng{11};
        for (int i = 0; i < 100000; ++i) {
            const double v = rng.uniform(-700.0, 700.0);
            QCOMPARE(roundHalfAway(v), int(std::lround(v)));
        }
    }

    // The ball's edge is a closed 8-connected ring one pixel from its border: a 4-connected
    // fill from the centre stays inside it.
    void ballGivesAClosedRingOfEdges()
    {
        const Config c;
        cv::Mat frame = greenField(c);
        const double d = 150;
        const cv::Point ball = drawBall(frame, c, d, 30);
        const EdgeStages s(c, frame);
        const double r = expectedRadius(c, d);
        QCOMPARE(int(s.edges.at<uchar>(ball)), 0);  // nothing inside the ball
        cv::Mat fill = s.edges.clone();
        const int inside = cv::floodFill(fill, ball, cv::Scalar(128), nullptr, 0, 0, 4);
        QVERIFY2(inside > M_PI * (r - 2) * (r - 2) && inside < M_PI * (r + 1) * (r + 1), qPrintable(QString::number(inside)));
        // ... and every edge pixel lies within a pixel of the drawn border.
        for (int y = 0; y < s.edges.rows; ++y)
            for (int x = 0; x < s.edges.cols; ++x)
                if (s.edges.at<uchar>(y, x)) QVERIFY(std::abs(std::hypot(x - ball.x, y - ball.y) - std::lround(r)) <= 1.5);
    }

    // What the tooltips of edges.canny_low/high say: on the binary image (levels 0 and 255) every
    // L1 Sobel gradient is a multiple of 510. Thresholds below 510 all give the same edges; up
    // to 1019 only the ring around a one-pixel speck drops out; from 1020 real borders break
    // (a low threshold); a high threshold from 1530 starts no edge at all.
    void cannyThresholdsBarelyMatterOnTheBinaryImage_data()
    {
        QTest::addColumn<int>("low");
        QTest::addColumn<int>("high");
        QTest::addColumn<QString>("change");
        QTest::newRow("0 / 0") << 0 << 0 << "none";
        QTest::newRow("10 / 500") << 10 << 500 << "none";
        QTest::newRow("509 / 509") << 509 << 509 << "none";
        QTest::newRow("60 / 510") << 60 << 510 << "speck";
        QTest::newRow("510 / 1019") << 510 << 1019 << "speck";
        QTest::newRow("1020 / 1020") << 1020 << 1020 << "borders";
        QTest::newRow("60 / 1530") << 60 << 1530 << "all";
    }
    void cannyThresholdsBarelyMatterOnTheBinaryImage()
    {
        QFETCH(int, low);
        QFETCH(int, high);
        QFETCH(QString, change);
        Config c;
        cv::Mat frame = greenField(c);
        for (int i = 0; i < 6; ++i) drawBall(frame, c, 80 + 25 * i, 60 * i + 10);
        cv::line(frame, pointAt(c, 90, 200), pointAt(c, 220, 235), kWhite, 3);
        const cv::Point2d speck = pointAt(c, 150, 300);  // one non-green pixel (sensor noise)
        frame.at<cv::Vec3b>(int(speck.y), int(speck.x)) = cv::Vec3b(235, 235, 235);
        c.edges.dropSpecks = false;  // the thresholds as set
        const EdgeStages thesis(c, frame);  // the thesis' 60 / 180
        QVERIFY(cv::countNonZero(thesis.edges) > 200);
        c.edges.cannyLow = low;
        c.edges.cannyHigh = high;
        const EdgeStages other(c, frame);
        cv::Mat changed = other.edges != thesis.edges;
        const int all = cv::countNonZero(changed);
        const cv::Rect aroundSpeck(int(speck.x) - 1, int(speck.y) - 1, 3, 3);
        const int atSpeck = cv::countNonZero(changed(aroundSpeck));
        if (change == "none") QCOMPARE(all, 0);
        if (change == "speck") QVERIFY2(atSpeck > 0 && all == atSpeck, qPrintable(QString("%1 %2").arg(all).arg(atSpeck)));
        if (change == "borders") QVERIFY2(all - atSpeck > 100, qPrintable(QString::number(all)));
        if (change == "all") QCOMPARE(cv::countNonZero(other.edges), 0);
    }

    // The same holds for the Canny inside cv::HoughCircles (opencv_hough.canny_high's tooltip).
    void houghCirclesCannyBarelyMattersOnTheBinaryImage()
    {
        const Config c;
        cv::Mat frame = greenField(c);
        for (int i = 0; i < 6; ++i) drawBall(frame, c, 80 + 25 * i, 60 * i + 10);
        const EdgeStages s(c, frame);
        const OpenCvHoughOptions o;
        auto circles = [&](double cannyHigh) {
            std::vector<cv::Vec3f> out;
            cv::HoughCircles(s.binary, out, cv::HOUGH_GRADIENT, o.dp, o.minDist, cannyHigh, o.accThreshold,
                             o.minRadius, o.maxRadius);
            return out;
        };
        const std::vector<cv::Vec3f> reference = circles(o.cannyHigh);
        QVERIFY(!reference.empty());
        QVERIFY(circles(509) == reference);
        QVERIFY(circles(1) == reference);
        QVERIFY(circles(1530).empty());  // no edge starts: the threshold does matter up there
    }

    void noEdgesAtTheMaskBorder()
    {
        const Config c;  // uniform carpet: the robot body and mirror rim must not make edges
        const EdgeStages s(c, greenField(c));
        QCOMPARE(cv::countNonZero(s.edges), 0);
    }
};

QTEST_GUILESS_MAIN(EdgesTest)
#include "core_edges_test.moc"
