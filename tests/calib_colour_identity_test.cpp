// The colour classes as data (colors.classes) segment exactly as the fixed classes did: the
// class name of every pixel of the demo session's frames and of optics-simulator frames (dim,
// bright cyan-green carpet, uneven dark carpet; relative black on, fitted configs) hashes to the
// value recorded with the fixed-class code (commit 6ec507d) before the change.
#include "calib/sim/optics/OpticsCell.h"
#include "core/ConfigParser.h"
#include "core/FrontEnd.h"

#include <opencv2/imgcodecs.hpp>

#include <QtTest>

#include <cstdio>

using namespace omnitune;

namespace {

// FNV-1a over the class name of every pixel, row by row ("unknown" for none).
std::uint64_t hashClassNames(const cv::Mat& classes, const ColourClasses& defs, std::uint64_t h)
{
    for (int y = 0; y < classes.rows; ++y)
        for (int x = 0; x < classes.cols; ++x) {
            for (char c : colourClassName(defs, ColorClass(classes.at<std::uint8_t>(y, x)))) {
                h ^= std::uint8_t(c);
                h *= 1099511628211ull;
            }
            h ^= '|';
            h *= 1099511628211ull;
        }
    return h;
}

constexpr std::uint64_t kFnvStart = 1469598103934665603ull;

std::uint64_t hashFrames(const std::vector<cv::Mat>& frames, const Config& config)
{
    FrontEnd frontEnd(config);
    std::uint64_t h = kFnvStart;
    cv::Mat classes, binary, edges;
    for (const cv::Mat& f : frames) {
        frontEnd.process(f, PixelFormat::Bgr8, classes, binary, edges);
        h = hashClassNames(classes, config.colors.classes, h);
    }
    return h;
}

}  // namespace

class ColourIdentityTest : public QObject {
    Q_OBJECT
private slots:
    void demoSession()
    {
        const ConfigLoad load = loadConfig(OMNITUNE_SOURCE_DIR "/sessions/demo/config.yml");
        QVERIFY(load.ok());
        std::vector<cv::Mat> frames;
        for (int i = 0; i < 24; ++i) {
            char path[64];
            std::snprintf(path, sizeof path, "/sessions/demo/frames/%06d.png", i);
            frames.push_back(cv::imread(OMNITUNE_SOURCE_DIR + std::string(path)));
            QVERIFY(!frames.back().empty());
        }
        QCOMPARE(hashFrames(frames, load.config), std::uint64_t(0x244a3115262ce13aull));
    }

    void opticsFrames_data()
    {
        QTest::addColumn<int>("ball");
        QTest::addColumn<int>("light");
        QTest::addColumn<int>("carpet");
        QTest::addColumn<quint64>("expected");
        QTest::newRow("orange, dim") << int(BallKind::Orange) << int(OpticsLight::Dim) << int(OpticsCarpet::Green)
                                     << quint64(0x854df9da43e99779ull);
        QTest::newRow("yellow-white, bright, cyan-green carpet")
            << int(BallKind::YellowWhite) << int(OpticsLight::Bright) << int(OpticsCarpet::CyanGreen)
            << quint64(0xbee8a202418cf2ccull);
        QTest::newRow("orange, uneven, dark carpet") << int(BallKind::Orange) << int(OpticsLight::Uneven)
                                                     << int(OpticsCarpet::DarkGreen) << quint64(0xc4909ef6b61372c4ull);
    }
    void opticsFrames()
    {
        QFETCH(int, ball);
        QFETCH(int, light);
        QFETCH(int, carpet);
        QFETCH(quint64, expected);
        OpticsCell cell;
        cell.ball = BallKind(ball);
        cell.light = OpticsLight(light);
        cell.carpet = OpticsCarpet(carpet);
        cell.frames = 2;
        const OpticsCellFrames r = renderCell(cell);
        QVERIFY2(r.calibrationError.empty(), r.calibrationError.c_str());
        // The hashes were recorded when the rim fit put the outer radius 4 px inside the rim (now
        // RimFitOptions::marginPx): the same ring, so the same pixels are segmented.
        Config config = r.fittedConfig;
        config.geometry.outerRadius -= 4.0 - MeasuredCalibrationOptions{}.rimMarginPx;
        QCOMPARE(quint64(hashFrames(r.frames, config)), expected);
    }
};

QTEST_GUILESS_MAIN(ColourIdentityTest)
#include "calib_colour_identity_test.moc"
