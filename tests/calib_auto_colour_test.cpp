// Automatic first colour calibration: on drawn frames with carpets the default green box does
// not fit (cyan-green, dark green in dim light), the dominant hue is found and the segmentation
// it gives calls the carpet green and the line, robot and ball something else.
#include "calib/colour/AutoColour.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

namespace {

struct Scene {
    cv::Mat frame;
    cv::Rect carpet{400, 300, 60, 60};
    cv::Rect line{150, 100, 300, 8};
    cv::Rect robot{100, 300, 40, 40};
    cv::Point ball{500, 150};
};

// A 640x480 frame: carpet of `carpetBgr` scaled by `light`, a white line, a black robot and an
// orange ball, all scaled by the light, with sensor noise.
Scene drawScene(cv::Scalar carpetBgr, double light, int seed)
{
    Scene s;
    s.frame = cv::Mat(480, 640, CV_8UC3, carpetBgr * light);
    cv::rectangle(s.frame, s.line, cv::Scalar(235, 235, 235) * light, cv::FILLED);
    cv::rectangle(s.frame, s.robot, cv::Scalar(15, 15, 15) * light, cv::FILLED);
    cv::circle(s.frame, s.ball, 12, cv::Scalar(20, 110, 240) * light, cv::FILLED);
    cv::Mat noise(480, 640, CV_16SC3);
    cv::RNG rng{std::uint64_t(seed)};
    rng.fill(noise, cv::RNG::NORMAL, 0, 2);
    cv::Mat wide;
    s.frame.convertTo(wide, CV_16SC3);
    wide += noise;
    wide.convertTo(s.frame, CV_8UC3);
    return s;
}

Geometry ring()
{
    GeometryOptions g;  // 640x480, centre (320, 240), radii 50..240
    return Geometry(g, cv::Mat());
}

double share(const cv::Mat& classes, const cv::Rect& r, ColorClass c)
{
    return double(cv::countNonZero(classes(r) == int(c))) / r.area();
}

cv::Mat segment(const ColorLutOptions& o, const cv::Mat& frame, const Geometry& g)
{
    cv::Mat classes(frame.size(), CV_8UC1, cv::Scalar(0));
    ColorLut(o).segment(frame, PixelFormat::Bgr8, g.spans(), classes);
    return classes;
}

}  // namespace

class AutoColourTest : public QObject {
    Q_OBJECT
private slots:
    void findsTheCarpet_data()
    {
        QTest::addColumn<double>("b");
        QTest::addColumn<double>("g");
        QTest::addColumn<double>("r");
        QTest::addColumn<double>("light");
        QTest::addColumn<int>("hue");
        // Hues in OpenCV's scale: cyan-green 88 lies outside the default green box (35..85)
        // and inside the cyan class (86..105).
        QTest::newRow("cyan-green carpet") << 150.0 << 160.0 << 30.0 << 1.0 << 88;
        QTest::newRow("cyan-green carpet, dim") << 150.0 << 160.0 << 30.0 << 0.35 << 88;
        QTest::newRow("dark-green carpet") << 25.0 << 80.0 << 15.0 << 1.0 << 65;
        QTest::newRow("dark-green carpet, dim") << 25.0 << 80.0 << 15.0 << 0.5 << 65;
        QTest::newRow("green carpet, bright") << 40.0 << 140.0 << 40.0 << 1.7 << 60;
    }
    void findsTheCarpet()
    {
        QFETCH(double, b);
        QFETCH(double, g);
        QFETCH(double, r);
        QFETCH(double, light);
        QFETCH(int, hue);
        const Scene s = drawScene(cv::Scalar(b, g, r), light, 3);
        const Geometry geometry = ring();
        const AutoColourResult res = autoColour({s.frame}, geometry, ColorLutOptions{});
        QVERIFY2(res.ok(), res.error ? res.error->c_str() : "");
        QVERIFY2(std::abs(res.carpetHue - hue) <= 2, qPrintable(QString::number(res.carpetHue)));
        QVERIFY(res.carpetPct > 80);
        const HsvRange& green = res.colors.classes[std::size_t(ColorClass::Green) - 1].boxes.front();
        QVERIFY(green.containsHue(hue));
        QVERIFY(res.colors.blackRelative);

        const cv::Mat classes = segment(res.colors, s.frame, geometry);
        QVERIFY2(share(classes, s.carpet, ColorClass::Green) > 0.99,
                 qPrintable(QString::number(share(classes, s.carpet, ColorClass::Green))));
        QVERIFY(share(classes, s.line, ColorClass::White) > 0.95);
        QVERIFY(share(classes, s.robot, ColorClass::Black) > 0.99);
        const cv::Rect ballCore(s.ball.x - 5, s.ball.y - 5, 10, 10);
        QCOMPARE(share(classes, ballCore, ColorClass::Green), 0.0);
        QCOMPARE(share(classes, ballCore, ColorClass::Black), 0.0);
    }

    // In a dim hall the ball is darker than the defaults' V floor (80): the calibration lowers
    // the ball class's floor to just above its black, so the ball is orange, not in no class
    // (where it merges with a shadowed line); in bright light the floor stays as it was.
    void dimBallKeepsItsClass()
    {
        const Scene dim = drawScene(cv::Scalar(40, 140, 40), 0.3, 6);
        const Geometry geometry = ring();
        const cv::Rect ballCore(dim.ball.x - 5, dim.ball.y - 5, 10, 10);
        QCOMPARE(share(segment(ColorLutOptions{}, dim.frame, geometry), ballCore, ColorClass::Orange), 0.0);
        const AutoColourResult res = autoColour({dim.frame}, geometry, ColorLutOptions{});
        QVERIFY(res.ok());
        QVERIFY(share(segment(res.colors, dim.frame, geometry), ballCore, ColorClass::Orange) > 0.95);

        const Scene bright = drawScene(cv::Scalar(40, 140, 40), 1.5, 7);
        const AutoColourResult lit = autoColour({bright.frame}, geometry, ColorLutOptions{});
        QVERIFY(lit.ok());
        const std::size_t orange = std::size_t(ColorClass::Orange) - 1;
        QCOMPARE(lit.colors.classes[orange].boxes.front().vMin, ColorLutOptions{}.classes[orange].boxes.front().vMin);
    }

    // The default colours fail on the cyan-green carpet (it is "cyan"); the calibration trims
    // the cyan class off the carpet's hues and says so.
    void cyanGreenCarpetNeedsIt()
    {
        const Scene s = drawScene(cv::Scalar(150, 160, 30), 1.0, 4);
        const Geometry geometry = ring();
        QVERIFY(share(segment(ColorLutOptions{}, s.frame, geometry), s.carpet, ColorClass::Green) < 0.5);
        const AutoColourResult res = autoColour({s.frame, s.frame}, geometry, ColorLutOptions{});
        QVERIFY(res.ok());
        const HsvRange& cyan = res.colors.classes[std::size_t(ColorClass::Cyan) - 1].boxes.front();
        QVERIFY(!cyan.enabled || !cyan.containsHue(88));
        QVERIFY(!res.notes.empty());
    }

    // A second field class (a dark-green region the user sampled) keeps its box; the first field
    // class gets the carpet; a note names the one kept.
    void secondFieldClassIsKept()
    {
        const Scene s = drawScene(cv::Scalar(40, 140, 40), 1.0, 5);
        ColorLutOptions start;
        ColourClassDef dark;
        dark.name = "dark_green";
        dark.role = ColourRole::Field;
        dark.boxes = {HsvRange{true, 50, 70, 80, 255, 20, 60}};
        start.classes.push_back(dark);
        const AutoColourResult res = autoColour({s.frame}, ring(), start);
        QVERIFY(res.ok());
        QCOMPARE(res.colors.classes.back(), dark);
        QVERIFY(res.colors.classes[std::size_t(ColorClass::Green) - 1] != start.classes[std::size_t(ColorClass::Green) - 1]);
        bool noted = false;
        for (const std::string& n : res.notes) noted = noted || n.find("dark_green") != std::string::npos;
        QVERIFY(noted);
    }

    void refusesWhatHasNoCarpet()
    {
        const Geometry geometry = ring();
        const cv::Mat grey(480, 640, CV_8UC3, cv::Scalar(90, 90, 90));
        AutoColourResult res = autoColour({grey}, geometry, ColorLutOptions{});
        QVERIFY(!res.ok());
        QVERIFY(res.error->find("colour") != std::string::npos);
        // Many colours, none dominant.
        cv::Mat confetti(480, 640, CV_8UC3);
        cv::Mat hsv(480, 640, CV_8UC3);
        cv::RNG rng(5);
        rng.fill(hsv, cv::RNG::UNIFORM, cv::Scalar(0, 150, 150), cv::Scalar(180, 255, 255));
        cv::cvtColor(hsv, confetti, cv::COLOR_HSV2BGR);
        res = autoColour({confetti}, geometry, ColorLutOptions{});
        QVERIFY(!res.ok());
        QVERIFY(res.error->find("no dominant hue") != std::string::npos);
        // A frame of the wrong size.
        res = autoColour({cv::Mat(100, 100, CV_8UC3, cv::Scalar(40, 140, 40))}, geometry, ColorLutOptions{});
        QVERIFY(!res.ok());
        QVERIFY(!autoColour({}, geometry, ColorLutOptions{}).ok());
    }
};

QTEST_GUILESS_MAIN(AutoColourTest)
#include "calib_auto_colour_test.moc"
