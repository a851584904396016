// Geometry (used pixels, mask, distances) and radial sensors.
#include "core/ConfigSchema.h"
#include "core/Geometry.h"
#include "core/RadialSensors.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

namespace {
GeometryOptions smallRing()
{
    GeometryOptions g;
    g.imageWidth = 101;
    g.imageHeight = 81;
    g.centerX = 50;
    g.centerY = 40;
    g.innerRadius = 10;
    g.outerRadius = 35;
    return g;
}
}  // namespace

class GeometryTest : public QObject {
    Q_OBJECT
private slots:
    void usedPixelsAreTheRing()
    {
        const Geometry geo(smallRing(), cv::Mat());
        QVERIFY(!geo.isUsed(50, 40));       // robot centre
        QVERIFY(!geo.isUsed(50 + 9, 40));   // inside the inner radius
        QVERIFY(geo.isUsed(50 + 10, 40));   // on it
        QVERIFY(geo.isUsed(50 + 35, 40));   // on the outer radius
        QVERIFY(!geo.isUsed(50 + 36, 40));  // beyond
        QVERIFY(!geo.isUsed(0, 0));
        QCOMPARE(geo.distanceAt(50 + 3, 40 + 4), 5.0f);
        // The ring's area, within the discretisation.
        const double area = M_PI * (35.0 * 35.0 - 10.0 * 10.0);
        QVERIFY(std::abs(double(geo.usedPixels().size()) - area) < 0.03 * area);
    }

    void spansAndUsedPixelsAgree()
    {
        const Geometry geo(smallRing(), cv::Mat());
        std::size_t fromSpans = 0;
        for (const RowSpan& s : geo.spans()) {
            QVERIFY(s.x0 < s.x1);
            for (int x = s.x0; x < s.x1; ++x) QVERIFY(geo.isUsed(x, s.y));
            fromSpans += std::size_t(s.x1 - s.x0);
        }
        QCOMPARE(fromSpans, geo.usedPixels().size());
        QCOMPARE(int(fromSpans), cv::countNonZero(geo.usedMask()));
    }

    void maskRemovesPixels()
    {
        cv::Mat mask(81, 101, CV_8UC1, cv::Scalar(255));
        cv::rectangle(mask, cv::Rect(70, 35, 20, 10), cv::Scalar(0), cv::FILLED);  // a support rod
        const Geometry geo(smallRing(), mask);
        QVERIFY(!geo.isUsed(75, 40));
        QVERIFY(geo.isUsed(25, 40));  // the mirror-image spot is kept
    }

    // A mask of the wrong size is a user error reported once, by checkConfig() with the sizes;
    // Geometry only asserts it (a caller that skipped checkConfig).
    void wrongMaskSizeIsAnError()
    {
        Config c;
        c.geometry = smallRing();
        c.mask = cv::Mat(80, 100, CV_8UC1, cv::Scalar(255));
        const auto issues = checkConfig(c);
        QCOMPARE(int(issues.size()), 1);
        QCOMPARE(QString::fromStdString(issues[0].key), QString("geometry.mask_file"));
        const QString message = QString::fromStdString(issues[0].message);
        QVERIFY2(message.contains("100x80") && message.contains("101x81"), qPrintable(message));
        QVERIFY_EXCEPTION_THROWN(Geometry(c.geometry, c.mask), cv::Exception);

        c.mask = cv::Mat(81, 101, CV_8UC3, cv::Scalar::all(255));
        const auto colour = checkConfig(c);
        QCOMPARE(int(colour.size()), 1);
        QVERIFY2(QString::fromStdString(colour[0].message).contains("one 8-bit channel"),
                 colour[0].message.c_str());
    }

    void oddFrameSizes_data()
    {
        QTest::addColumn<int>("w");
        QTest::addColumn<int>("h");
        QTest::newRow("640x480 Flea2") << 640 << 480;
        QTest::newRow("480x480 cropped") << 480 << 480;
        QTest::newRow("505x480 odd crop") << 505 << 480;
    }
    void oddFrameSizes()
    {
        QFETCH(int, w);
        QFETCH(int, h);
        GeometryOptions g;
        g.imageWidth = w;
        g.imageHeight = h;
        g.centerX = w / 2.0;
        g.centerY = h / 2.0;
        const Geometry geo(g, cv::Mat());
        QCOMPARE(geo.usedMask().cols, w);
        QCOMPARE(geo.usedMask().rows, h);
        QVERIFY(!geo.usedPixels().empty());
        QVERIFY(geo.usedPixels().back() < w * h);
    }

    void sensorRaysStayInTheRing()
    {
        const Geometry geo(smallRing(), cv::Mat());
        RadialSensorOptions o;
        o.count = 8;
        o.innerRadius = 10;
        o.outerRadius = 35;
        const RadialSensors sensors(o, geo);
        QCOMPARE(sensors.count(), 8);
        for (int r = 0; r < sensors.count(); ++r) {
            const auto& px = sensors.pixels(r);
            QVERIFY(px.size() >= 15);  // 25 px of ray, fewer pixels on diagonals
            for (const auto& p : px) QVERIFY(geo.isUsed(p.x, p.y));
            QVERIFY(px.front().radius < px.back().radius);
        }
        // Ray 0 runs along +x, ray 2 (90 degrees) straight up in the image.
        QCOMPARE(sensors.pixels(0).back().y, 40);
        QVERIFY(sensors.pixels(0).back().x > 80);
        QCOMPARE(sensors.pixels(2).back().x, 50);
        QVERIFY(sensors.pixels(2).back().y < 10);
    }

    void sensorAngleOffsetTurnsEveryRay()
    {
        const Geometry geo(smallRing(), cv::Mat());
        RadialSensorOptions o;
        o.count = 8;
        o.innerRadius = 10;
        o.outerRadius = 35;
        o.angleOffsetDeg = 90.0;  // ray 0 where ray 2 was: straight up
        const RadialSensors sensors(o, geo);
        QCOMPARE(sensors.angle(0), M_PI / 2);
        QCOMPARE(radialSensorAngle(o, 1), M_PI / 2 + M_PI / 4);
        QCOMPARE(sensors.pixels(0).back().x, 50);
        QVERIFY(sensors.pixels(0).back().y < 10);
        QCOMPARE(sensors.pixels(6).back().y, 40);  // 90 + 270 degrees: along +x
        QVERIFY(sensors.pixels(6).back().x > 80);
    }

    void sensorRunsFollowTheClasses()
    {
        const Geometry geo(smallRing(), cv::Mat());
        RadialSensorOptions o;
        o.count = 4;
        o.innerRadius = 10;
        o.outerRadius = 35;
        const RadialSensors sensors(o, geo);
        cv::Mat classes(81, 101, CV_8UC1, cv::Scalar(int(ColorClass::Green)));
        // A white line crossing ray 0 at 20..22 px from the centre, then an obstacle from 30 px.
        cv::rectangle(classes, cv::Rect(70, 0, 3, 81), cv::Scalar(int(ColorClass::White)), cv::FILLED);
        cv::rectangle(classes, cv::Rect(80, 0, 21, 81), cv::Scalar(int(ColorClass::Black)), cv::FILLED);
        std::vector<ClassRun> runs;
        sensors.runs(classes, 0, runs);
        QCOMPARE(int(runs.size()), 4);
        QCOMPARE(runs[0].colorClass, ColorClass::Green);
        QCOMPARE(runs[1].colorClass, ColorClass::White);
        QCOMPARE(runs[1].startRadius, 20.f);
        QCOMPARE(runs[1].endRadius, 22.f);
        QCOMPARE(runs[2].colorClass, ColorClass::Green);
        QCOMPARE(runs[3].colorClass, ColorClass::Black);
        QCOMPARE(runs[3].startRadius, 30.f);
        sensors.runs(classes, 2, runs);  // straight up: all carpet
        QCOMPARE(int(runs.size()), 1);
    }
};

QTEST_GUILESS_MAIN(GeometryTest)
#include "core_geometry_test.moc"
