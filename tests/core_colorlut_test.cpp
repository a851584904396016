// Colour LUT: classes of typical colours, agreement with direct HSV classification, hue
// wrap-around, and the UYVY path agreeing with the BGR path.
#include "core/ColorLut.h"
#include "core/ConfigSchema.h"
#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
Q_DECLARE_METATYPE(omnitune::ColorClass)

namespace {

ColorClass direct(const ColorLutOptions& o, cv::Vec3b bgr)
{
    cv::Mat px(1, 1, CV_8UC3, cv::Scalar(bgr[0], bgr[1], bgr[2]));
    cv::Mat hsv;
    cv::cvtColor(px, hsv, cv::COLOR_BGR2HSV);
    const cv::Vec3b h = hsv.at<cv::Vec3b>(0, 0);
    return classifyHsv(o.classes, h[0], h[1], h[2]);
}

// BGR -> full-range BT.601 YUV, the inverse of yuvToBgr.
cv::Vec3b bgrToYuv(cv::Vec3b bgr)
{
    const double b = bgr[0], g = bgr[1], r = bgr[2];
    const double y = 0.299 * r + 0.587 * g + 0.114 * b;
    return {cv::saturate_cast<uchar>(y), cv::saturate_cast<uchar>(128 + (b - y) / 1.772),
            cv::saturate_cast<uchar>(128 + (r - y) / 1.402)};
}

}  // namespace

class ColorLutTest : public QObject {
    Q_OBJECT
private slots:
    void typicalColors_data()
    {
        QTest::addColumn<int>("b");
        QTest::addColumn<int>("g");
        QTest::addColumn<int>("r");
        QTest::addColumn<ColorClass>("expected");
        QTest::newRow("carpet green") << 40 << 140 << 40 << ColorClass::Green;
        QTest::newRow("dark carpet in shade") << 30 << 80 << 25 << ColorClass::Green;
        QTest::newRow("line white") << 235 << 235 << 235 << ColorClass::White;
        QTest::newRow("grey-white line far away") << 190 << 200 << 195 << ColorClass::White;
        QTest::newRow("robot black") << 20 << 20 << 20 << ColorClass::Black;
        QTest::newRow("orange ball") << 20 << 110 << 240 << ColorClass::Orange;
        QTest::newRow("cyan marker") << 230 << 200 << 20 << ColorClass::Cyan;
        QTest::newRow("magenta marker") << 200 << 30 << 210 << ColorClass::Magenta;
        QTest::newRow("blue ball is unknown") << 200 << 60 << 30 << ColorClass::Unknown;
        QTest::newRow("red panel is unknown") << 30 << 30 << 200 << ColorClass::Unknown;
    }
    void typicalColors()
    {
        QFETCH(int, b);
        QFETCH(int, g);
        QFETCH(int, r);
        QFETCH(ColorClass, expected);
        const ColorLutOptions o;
        const ColorLut lut(o);
        const cv::Vec3b bgr{uchar(b), uchar(g), uchar(r)};
        QCOMPARE(direct(o, bgr), expected);
        QCOMPARE(lut.classifyBgr(bgr[0], bgr[1], bgr[2]), expected);
    }

    // With 8 bits the table is exact: it must agree with direct classification everywhere.
    void exactTableAgreesWithDirectHsv()
    {
        ColorLutOptions o;
        o.bits = 8;
        o.blackRelative = false;  // relative black depends on the frame (tested below)
        const ColorLut lut(o);
        cv::RNG rng(7);
        for (int i = 0; i < 20000; ++i) {
            const cv::Vec3b c(uchar(rng.uniform(0, 256)), uchar(rng.uniform(0, 256)), uchar(rng.uniform(0, 256)));
            QCOMPARE(lut.classifyBgr(c[0], c[1], c[2]), direct(o, c));
        }
    }

    // The default (quantised) table agrees with the direct classification on every bin centre.
    void defaultTableAgreesOnBinCentres()
    {
        ColorLutOptions o;
        o.blackRelative = false;
        const ColorLut lut(o);
        const int step = 1 << (8 - o.bits);
        int checked = 0;
        for (int b = step / 2; b < 256; b += 3 * step)
            for (int g = step / 2; g < 256; g += 3 * step)
                for (int r = step / 2; r < 256; r += 3 * step, ++checked)
                    QCOMPARE(lut.classifyBgr(uchar(b), uchar(g), uchar(r)), direct(o, cv::Vec3b(uchar(b), uchar(g), uchar(r))));
        QVERIFY(checked > 1000);
    }

    void hueWrapAround_data()
    {
        QTest::addColumn<int>("hMin");
        QTest::addColumn<int>("hMax");
        QTest::addColumn<int>("hue");
        QTest::addColumn<bool>("inside");
        QTest::newRow("plain range, inside") << 5 << 22 << 10 << true;
        QTest::newRow("plain range, outside") << 5 << 22 << 30 << false;
        QTest::newRow("wrapped range, upper part") << 170 << 10 << 175 << true;
        QTest::newRow("wrapped range, zero") << 170 << 10 << 0 << true;
        QTest::newRow("wrapped range, lower part") << 170 << 10 << 10 << true;
        QTest::newRow("wrapped range, middle is out") << 170 << 10 << 90 << false;
        QTest::newRow("wrapped range, just below start") << 170 << 10 << 169 << false;
    }
    void hueWrapAround()
    {
        QFETCH(int, hMin);
        QFETCH(int, hMax);
        QFETCH(int, hue);
        QFETCH(bool, inside);
        HsvRange r{true, hMin, hMax, 0, 255, 0, 255};
        QCOMPARE(r.contains(hue, 200, 200), inside);
    }

    // A red class spanning hue 0 must catch reds on both sides of the wrap through the LUT.
    void wrappedClassThroughLut()
    {
        ColorLutOptions o;
        o.classes[std::size_t(ColorClass::Magenta) - 1].boxes = {HsvRange{true, 170, 8, 150, 255, 80, 255}};
        o.classes[std::size_t(ColorClass::Orange) - 1].enabled = false;
        const ColorLut lut(o);
        QCOMPARE(lut.classifyBgr(20, 20, 220), ColorClass::Magenta);   // hue 0
        QCOMPARE(lut.classifyBgr(60, 20, 220), ColorClass::Magenta);   // hue ~174
        QCOMPARE(lut.classifyBgr(20, 50, 220), ColorClass::Magenta);   // hue ~4
        QCOMPARE(lut.classifyBgr(20, 220, 220), ColorClass::Unknown);  // yellow, hue 30
    }

    void disabledClassNeverMatches()
    {
        ColorLutOptions o;
        o.classes[std::size_t(ColorClass::Green) - 1].enabled = false;
        const ColorLut lut(o);
        QCOMPARE(lut.classifyBgr(40, 140, 40), ColorClass::Unknown);
    }

    void segmentsOnlyInsideSpans()
    {
        GeometryOptions g;
        g.imageWidth = 64;
        g.imageHeight = 48;
        g.centerX = 32;
        g.centerY = 24;
        g.innerRadius = 5;
        g.outerRadius = 20;
        const Geometry geo(g, cv::Mat());
        const ColorLut lut{ColorLutOptions{}};
        cv::Mat frame(48, 64, CV_8UC3, cv::Scalar(40, 140, 40));
        cv::Mat classes(48, 64, CV_8UC1, cv::Scalar(0));
        lut.segment(frame, PixelFormat::Bgr8, geo.spans(), classes);
        QCOMPARE(int(classes.at<uchar>(24, 32 + 10)), int(ColorClass::Green));  // in the ring
        QCOMPARE(int(classes.at<uchar>(24, 32)), int(ColorClass::Unknown));     // robot centre
        QCOMPARE(int(classes.at<uchar>(0, 0)), int(ColorClass::Unknown));       // outside mirror
        QCOMPARE(cv::countNonZero(classes), int(geo.usedPixels().size()));
    }

    // A dim carpet (V ~ 45) with noise: the thesis' fixed black (V <= 60) takes it all as black;
    // relative black keeps it green and still finds a robot that is dark next to it.
    void dimCarpetStaysGreenWithRelativeBlack()
    {
        GeometryOptions g;
        g.imageWidth = 80;
        g.imageHeight = 80;
        g.centerX = 40;
        g.centerY = 40;
        g.innerRadius = 0;
        g.outerRadius = 200;
        const Geometry geo(g, cv::Mat());
        cv::Mat frame(80, 80, CV_8UC3, cv::Scalar(11, 42, 13));  // dim carpet, hue ~61, V ~45
        cv::Mat noise(80, 80, CV_8UC3);
        cv::RNG rng(7);
        rng.fill(noise, cv::RNG::UNIFORM, 0, 7);
        cv::add(frame, noise, frame);
        cv::rectangle(frame, cv::Rect(10, 10, 12, 12), cv::Scalar(4, 5, 4), cv::FILLED);  // robot, V ~5
        auto share = [&](const cv::Mat& classes, ColorClass c, cv::Rect r) {
            return double(cv::countNonZero(classes(r) == int(c))) / r.area();
        };
        const cv::Rect carpet(40, 40, 30, 30);
        const cv::Rect robot(12, 12, 8, 8);

        ColorLutOptions thesis;
        thesis.blackRelative = false;
        cv::Mat a(80, 80, CV_8UC1, cv::Scalar(0));
        SegmentStats stats;
        ColorLut(thesis).segment(frame, PixelFormat::Bgr8, geo.spans(), a, &stats);
        QVERIFY(share(a, ColorClass::Black, carpet) > 0.99);
        QCOMPARE(stats.carpetV, -1);

        ColorLutOptions relative;
        relative.blackRelative = true;
        const ColorLut lut(relative);
        cv::Mat b(80, 80, CV_8UC1, cv::Scalar(0));
        lut.segment(frame, PixelFormat::Bgr8, geo.spans(), b, &stats);
        QVERIFY(share(b, ColorClass::Green, carpet) > 0.99);
        QCOMPARE(share(b, ColorClass::Black, robot), 1.0);
        QVERIFY(std::abs(stats.carpetV - 45) <= 8);
        QCOMPARE(stats.blackV, int(std::lround(relative.blackVRatio * stats.carpetV)));

        // The same frame in bright light: black's threshold follows the carpet up.
        cv::Mat bright;
        frame.convertTo(bright, -1, 3.0);
        lut.segment(bright, PixelFormat::Bgr8, geo.spans(), b, &stats);
        QVERIFY(stats.carpetV > 120);
        QVERIFY(share(b, ColorClass::Green, carpet) > 0.99);
        QCOMPARE(share(b, ColorClass::Black, robot), 1.0);
        // Without a carpet in view, black falls back to the fixed v_max.
        const cv::Mat grey(80, 80, CV_8UC3, cv::Scalar(50, 50, 50));
        lut.segment(grey, PixelFormat::Bgr8, geo.spans(), b, &stats);
        QCOMPARE(stats.carpetV, -1);
        QCOMPARE(stats.blackV, 60);
        QCOMPARE(share(b, ColorClass::Black, carpet), 1.0);
        // One colour alone is classified as without a carpet: black up to v_max.
        QCOMPARE(lut.classifyBgr(14, 45, 16), ColorClass::Black);
        QCOMPARE(lut.classifyBgr(30, 80, 25), ColorClass::Green);
    }

    // Pixels outside the ring and masked pixels (rods, robot body) stay Unknown, so validation
    // can treat them as unknown.
    void maskedPixelsStayUnknown()
    {
        GeometryOptions g;
        g.imageWidth = 64;
        g.imageHeight = 48;
        g.centerX = 32;
        g.centerY = 24;
        g.innerRadius = 5;
        g.outerRadius = 20;
        cv::Mat mask(48, 64, CV_8UC1, cv::Scalar(255));
        cv::rectangle(mask, cv::Rect(40, 20, 6, 8), cv::Scalar(0), cv::FILLED);  // a rod
        const Geometry geo(g, mask);
        for (bool relative : {false, true}) {
            ColorLutOptions o;
            o.blackRelative = relative;
            const cv::Mat frame(48, 64, CV_8UC3, cv::Scalar(20, 20, 20));  // black everywhere
            cv::Mat classes(48, 64, CV_8UC1, cv::Scalar(0));
            ColorLut(o).segment(frame, PixelFormat::Bgr8, geo.spans(), classes);
            QCOMPARE(int(classes.at<uchar>(24, 42)), int(ColorClass::Unknown));  // masked
            QCOMPARE(int(classes.at<uchar>(0, 0)), int(ColorClass::Unknown));    // outside the mirror
            QCOMPARE(int(classes.at<uchar>(24, 32)), int(ColorClass::Unknown));  // robot centre
            QCOMPARE(int(classes.at<uchar>(24, 20)), int(ColorClass::Black));    // processed
            QCOMPARE(cv::countNonZero(classes), int(geo.usedPixels().size()));
        }
    }

    // A UYVY frame made from BGR colours segments like the BGR frame.
    void uyvyAgreesWithBgr()
    {
        const std::vector<cv::Vec3b> colors = {{40, 140, 40}, {235, 235, 235}, {20, 20, 20},
                                               {20, 110, 240}, {230, 200, 20}, {200, 30, 210}};
        const int w = 2 * int(colors.size());
        cv::Mat bgr(1, w, CV_8UC3);
        cv::Mat uyvy(1, w, CV_8UC2);
        for (int i = 0; i < int(colors.size()); ++i) {
            // Both pixels of a pair share U and V, so give a pair one colour.
            bgr.at<cv::Vec3b>(0, 2 * i) = bgr.at<cv::Vec3b>(0, 2 * i + 1) = colors[std::size_t(i)];
            const cv::Vec3b yuv = bgrToYuv(colors[std::size_t(i)]);
            uchar* p = uyvy.ptr<uchar>(0) + 4 * i;
            p[0] = yuv[1];
            p[1] = yuv[0];
            p[2] = yuv[2];
            p[3] = yuv[0];
        }
        GeometryOptions g;
        g.imageWidth = w;
        g.imageHeight = 1;
        g.centerX = 0;
        g.centerY = 0;
        g.innerRadius = 0;
        g.outerRadius = 1000;
        const Geometry geo(g, cv::Mat());
        const ColorLut lut{ColorLutOptions{}};
        cv::Mat a(1, w, CV_8UC1, cv::Scalar(0));
        cv::Mat b(1, w, CV_8UC1, cv::Scalar(0));
        lut.segment(bgr, PixelFormat::Bgr8, geo.spans(), a);
        lut.segment(uyvy, PixelFormat::Uyvy, geo.spans(), b);
        for (int x = 0; x < w; ++x) QCOMPARE(int(b.at<uchar>(0, x)), int(a.at<uchar>(0, x)));
        QCOMPARE(int(a.at<uchar>(0, 6)), int(ColorClass::Orange));

        cv::Mat back;
        convertUyvyToBgr(uyvy, back);
        for (int x = 0; x < w; ++x)
            for (int ch = 0; ch < 3; ++ch)
                QVERIFY(std::abs(back.at<cv::Vec3b>(0, x)[ch] - bgr.at<cv::Vec3b>(0, x)[ch]) <= 2);
    }

    void rejectsBadBits()
    {
        ColorLutOptions o;
        o.bits = 9;
        QVERIFY_EXCEPTION_THROWN(ColorLut{o}, cv::Exception);  // a programmer error: checkConfig reports it
        Config c;
        c.colors = o;
        const auto issues = checkConfig(c);
        QVERIFY(!issues.empty());
        QCOMPARE(QString::fromStdString(issues.front().key), QString("colors.lut_bits"));
    }
};

QTEST_GUILESS_MAIN(ColorLutTest)
#include "core_colorlut_test.moc"
