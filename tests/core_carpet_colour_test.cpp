// The carpet's colour next to a candidate (core/CarpetColour.h) on a carpet whose hues straddle
// the 0 / 179 wrap (a red-ish carpet): its hue is the circular mean (about 0, not 90) with a
// small spread, so a pixel of the carpet's red matches it and a cyan one does not. The plain
// mean of hues 176 and 3 is 89.5 with a spread near 87: every hue would have matched.
#include "core/CarpetColour.h"
#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

namespace {

// A square frame of carpet whose pixels alternate between hues `a` and `b` (S 200, V 150).
cv::Mat carpetOf(int a, int b)
{
    cv::Mat hsv(120, 120, CV_8UC3);
    for (int y = 0; y < hsv.rows; ++y)
        for (int x = 0; x < hsv.cols; ++x) hsv.at<cv::Vec3b>(y, x) = cv::Vec3b(std::uint8_t((x / 3 + y / 3) % 2 ? a : b), 200, 150);
    cv::Mat bgr;
    cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
    return bgr;
}

Geometry square()
{
    GeometryOptions g;
    g.imageWidth = 120;
    g.imageHeight = 120;
    g.centerX = 60;
    g.centerY = 60;
    g.innerRadius = 0;
    g.outerRadius = 80;
    return Geometry(g, cv::Mat());
}

// One field class that takes every pixel: the ring's pixels all count as carpet.
ColourRoles fieldEverywhere()
{
    ColourClassDef red;
    red.name = "red_carpet";
    red.role = ColourRole::Field;
    red.boxes = {HsvRange{}};
    return ColourRoles(ColourClasses{red});
}

}  // namespace

class CarpetColourTest : public QObject {
    Q_OBJECT
private slots:
    void redCarpetHueWrapsThroughZero()
    {
        const cv::Mat frame = carpetOf(176, 3);
        const cv::Mat classes(frame.size(), CV_8UC1, cv::Scalar(1));
        const CarpetColour cc =
            CarpetColour::around(FrameColour(frame, PixelFormat::Bgr8), classes, square(), fieldEverywhere(), 60, 60, 10, 40);
        QVERIFY(cc.valid());
        // Circular mean of 176 and 3: about 179.5 (= -0.5), within a step of the wrap.
        const double offset = std::min(cc.hue(), 180.0 - cc.hue());
        QVERIFY2(offset < 2.0, qPrintable(QString::number(cc.hue())));
        const CarpetTolerance t;  // 3 spreads, at least 8 hue steps
        QVERIFY(cc.matches(Hsv{178, 200, 150}, t));
        QVERIFY(cc.matches(Hsv{2, 200, 150}, t));
        QVERIFY(!cc.matches(Hsv{90, 200, 150}, t));  // cyan is not this carpet
        QVERIFY(!cc.matches(Hsv{30, 200, 150}, t));  // nor yellow
    }

    void greenCarpetAsBefore()
    {
        const cv::Mat frame = carpetOf(58, 62);
        const cv::Mat classes(frame.size(), CV_8UC1, cv::Scalar(1));
        const CarpetColour cc =
            CarpetColour::around(FrameColour(frame, PixelFormat::Bgr8), classes, square(), fieldEverywhere(), 60, 60, 10, 40);
        QVERIFY(cc.valid());
        QVERIFY2(std::abs(cc.hue() - 60.0) < 1.0, qPrintable(QString::number(cc.hue())));
        QVERIFY(cc.matches(Hsv{60, 200, 150}, CarpetTolerance{}));
        QVERIFY(!cc.matches(Hsv{10, 200, 150}, CarpetTolerance{}));
    }
};

QTEST_GUILESS_MAIN(CarpetColourTest)
#include "core_carpet_colour_test.moc"
