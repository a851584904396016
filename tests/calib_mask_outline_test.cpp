// The mask outline the workbench draws: the border of the processed region, hole included.
#include "calib/mask/MaskOutline.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

class MaskOutlineTest : public QObject {
    Q_OBJECT
private slots:
    void outlinesTheProcessedRingAndItsHole()
    {
        cv::Mat mask(100, 100, CV_8UC1, cv::Scalar(0));
        cv::rectangle(mask, cv::Rect(10, 10, 80, 80), cv::Scalar(255), cv::FILLED);
        cv::rectangle(mask, cv::Rect(40, 40, 20, 20), cv::Scalar(0), cv::FILLED);  // the robot body
        const Polylines lines = maskOutline(mask);
        QCOMPARE(int(lines.size()), 2);
        cv::Rect outer, inner;
        for (const auto& l : lines) {
            const cv::Rect box = cv::boundingRect(l);
            (box.width > 50 ? outer : inner) = box;
        }
        QCOMPARE(outer, cv::Rect(10, 10, 80, 80));
        QVERIFY(inner.x >= 39 && inner.x <= 40 && inner.width >= 20 && inner.width <= 22);
    }
    void noMaskNoLines()
    {
        QVERIFY(maskOutline(cv::Mat()).empty());
        QVERIFY(maskOutline(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))).empty());
    }
};

QTEST_MAIN(MaskOutlineTest)
#include "calib_mask_outline_test.moc"
