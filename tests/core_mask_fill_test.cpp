// opencv_hough.mask_fill_px (core/MaskFill.h): masked ring pixels beside non-green ones are
// non-green in HoughCircles' input, so a ball crossed by a masked support rod is one disc again.
// (What it buys on rendered rods is tests/calib_eval_mask_fill_test.cpp.)
#include "core/Geometry.h"
#include "core/MaskFill.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

class MaskFillTest : public QObject {
    Q_OBJECT
private slots:
    // Inside the disc the rod turns non-green; away from it the rod stays green.
    void fillsTheRodAcrossADiscOnly()
    {
        GeometryOptions g;
        cv::Mat mask(g.imageHeight, g.imageWidth, CV_8UC1, cv::Scalar(255));
        const cv::Rect rod(400, 0, 6, g.imageHeight);
        mask(rod).setTo(0);
        const Geometry geometry(g, mask);
        QVERIFY(!geometry.maskedInRing().empty());
        cv::Mat binary(mask.size(), CV_8UC1, cv::Scalar(255));
        cv::circle(binary, cv::Point(403, 240), 12, cv::Scalar(0), cv::FILLED);
        binary(rod).setTo(255);  // as makeBinary paints masked pixels
        MaskFill fill;
        const cv::Mat& filled = fill.apply(binary, geometry, 4);
        QCOMPARE(int(filled.at<std::uint8_t>(240, 403)), 0);    // the rod inside the ball
        QCOMPARE(int(filled.at<std::uint8_t>(100, 403)), 255);  // the rod on bare carpet
        QCOMPARE(int(filled.at<std::uint8_t>(240, 420)), 255);  // carpet is never touched
        QCOMPARE(cv::countNonZero(filled != binary) > 0, true);
        // Off, or nothing masked in the ring: the binary image itself.
        QCOMPARE(&fill.apply(binary, geometry, 0), &binary);
        const Geometry unmasked(g, cv::Mat());
        QVERIFY(unmasked.maskedInRing().empty());
        QCOMPARE(&fill.apply(binary, unmasked, 4), &binary);
    }
};

QTEST_APPLESS_MAIN(MaskFillTest)
#include "core_mask_fill_test.moc"
