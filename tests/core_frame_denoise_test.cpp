// denoise.above_noise (issue 9): a noisy frame is blurred before segmentation, a clean one is
// not. The noise estimate must tell the two apart, the blur must keep flat areas flat and
// spread a point evenly, and the pipeline must segment the blurred frame.
#include "DrawnScene.h"

#include "calib/sim/UyvyEncoding.h"
#include "core/ColorLut.h"
#include "core/FrameDenoise.h"
#include "core/FrameNoise.h"
#include "core/FrontEnd.h"
#include "core/Pipeline.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {

// The drawn green field with Gaussian noise of `sigma` levels on every channel (fixed seed).
cv::Mat noisyField(const Config& c, double sigma)
{
    cv::Mat noise(c.geometry.imageHeight, c.geometry.imageWidth, CV_16SC3);
    cv::RNG rng(12345);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma);
    cv::Mat field;
    greenField(c).convertTo(field, CV_16SC3);
    cv::Mat out;
    cv::add(field, noise, field);
    field.convertTo(out, CV_8UC3);  // saturates
    return out;
}

// A field with lines and a ball: edges, but no noise.
cv::Mat cleanScene(const Config& c)
{
    cv::Mat frame = greenField(c);
    cv::line(frame, rounded(pointAt(c, 80, 0)), rounded(pointAt(c, 220, 0)), kWhite, 5);
    cv::circle(frame, rounded(pointAt(c, 0, 0)), 150, kWhite, 5);
    drawBall(frame, c, 120, 60);
    return frame;
}

cv::Mat toUyvy(const cv::Mat& bgr)
{
    cv::Mat uyvy;
    convertBgrToUyvy(bgr, uyvy);
    return uyvy;
}

// Share of the ring's pixels that are not of a field class.
double nonFieldShare(const FrontEnd& f, const cv::Mat& classes)
{
    long other = 0;
    long all = 0;
    for (const RowSpan& s : f.geometry().spans()) {
        const std::uint8_t* c = classes.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) other += !f.roles().field(c[x]);
        all += s.x1 - s.x0;
    }
    return all ? double(other) / double(all) : 0.0;
}

}  // namespace

class FrameDenoiseTest : public QObject {
    Q_OBJECT

private slots:
    void noiseEstimateTellsNoisyFromClean()
    {
        const Config c;
        const FrontEnd f(c);
        const double clean = frameNoiseSigma(cleanScene(c), PixelFormat::Bgr8, f.geometry().spans());
        const double noisy = frameNoiseSigma(noisyField(c, 8.0), PixelFormat::Bgr8, f.geometry().spans());
        QVERIFY2(clean < 2.0, qPrintable(QString("clean scene reads %1").arg(clean)));
        // A Gaussian of sigma 8 reads as 8 (the estimator is unbiased on flat areas).
        QVERIFY2(std::abs(noisy - 8.0) < 0.5, qPrintable(QString("sigma 8 reads %1").arg(noisy)));
    }

    void blursOnlyNoisyFrames()
    {
        Config c;
        c.denoise.aboveNoise = 4.0;
        const FrontEnd f(c);
        FrameDenoiser d(c.denoise);
        const cv::Mat clean = cleanScene(c);
        QCOMPARE(&d.apply(clean, PixelFormat::Bgr8, f.geometry().spans()), &clean);
        QVERIFY(!d.lastBlurred());
        QVERIFY(d.lastNoise() > 0.0);

        const cv::Mat noisy = noisyField(c, 8.0);
        const cv::Mat& out = d.apply(noisy, PixelFormat::Bgr8, f.geometry().spans());
        QVERIFY(&out != &noisy);
        QVERIFY(d.lastBlurred());
        QCOMPARE(out.size(), noisy.size());
        QCOMPARE(out.type(), noisy.type());
        // The 3x3 Gaussian (sigma 0.8) keeps about half the noise's sigma.
        const double after = frameNoiseSigma(out, PixelFormat::Bgr8, f.geometry().spans());
        QVERIFY2(after < 0.6 * d.lastNoise(), qPrintable(QString("%1 -> %2").arg(d.lastNoise()).arg(after)));

        // Off: never measured or blurred.
        c.denoise.aboveNoise = 0.0;
        FrameDenoiser off(c.denoise);
        QCOMPARE(&off.apply(noisy, PixelFormat::Bgr8, f.geometry().spans()), &noisy);
        QCOMPARE(off.lastNoise(), 0.0);
    }

    // The thesis' IIDC camera delivers YUV 4:2:2: its frames are measured (on the green rebuilt
    // from Y, U and V) and their colour blurred in their own format, so the robot's path gets
    // the blur too.
    void uyvyFramesAreMeasuredAndBlurred()
    {
        Config c;
        c.denoise.aboveNoise = 3.0;
        const FrontEnd f(c);
        FrameDenoiser d(c.denoise);
        const cv::Mat clean = toUyvy(cleanScene(c));
        QCOMPARE(&d.apply(clean, PixelFormat::Uyvy, f.geometry().spans()), &clean);
        QVERIFY(!d.lastBlurred());
        QVERIFY2(d.lastNoise() > 0.0 && d.lastNoise() < 2.0, qPrintable(QString("clean reads %1").arg(d.lastNoise())));

        // Pairs share U and V, which averages part of the noise away: sigma 8 reads lower than
        // on BGR, still far above a clean frame.
        const cv::Mat noisy = toUyvy(noisyField(c, 8.0));
        const cv::Mat& out = d.apply(noisy, PixelFormat::Uyvy, f.geometry().spans());
        const double before = d.lastNoise();
        QVERIFY2(before > 5.0 && before < 8.0, qPrintable(QString("sigma 8 reads %1").arg(before)));
        QVERIFY(d.lastBlurred());
        QCOMPARE(out.type(), CV_8UC2);
        QCOMPARE(out.size(), noisy.size());
        // Its colour (U, V) is smoothed, its Y kept as captured.
        // Bytes first, first + 4, ... (0: U, 2: V, 1: Y0) over a flat patch of the ring.
        auto spread = [](const cv::Mat& m, int first) {
            std::vector<double> v;
            for (int y = 200; y < 280; ++y)
                for (int b = 2 * 400 + first; b < 2 * 560; b += 4) v.push_back(m.ptr<std::uint8_t>(y)[b]);
            cv::Scalar mean, sd;
            cv::meanStdDev(v, mean, sd);
            return sd[0];
        };
        for (int first : {0, 2})
            QVERIFY2(spread(out, first) < 0.6 * spread(noisy, first),
                     qPrintable(QString("byte %1: %2 -> %3").arg(first).arg(spread(noisy, first)).arg(spread(out, first))));
        QCOMPARE(spread(out, 1), spread(noisy, 1));
    }

    // In UYVY (U0 Y0 V0 Y1) only colour is blurred: a Y stays as captured (a far ball keeps its
    // outline), a U spreads to the U values above and below and, weakly, of the pairs beside it
    // (4 bytes away), never into V or Y.
    void uyvyBlurSpreadsOnlyColour()
    {
        Config c;
        c.denoise.aboveNoise = 0.001;
        const FrontEnd f(c);
        FrameDenoiser d(c.denoise);
        cv::Mat frame(c.geometry.imageHeight, c.geometry.imageWidth, CV_8UC2, cv::Scalar(128, 100));
        frame.at<cv::Vec2b>(0, 0)[0] = 131;  // texture for the estimate (outside the ring)
        const int y = 240, x = 470;          // an even pixel: its pair starts at byte 2 x
        std::uint8_t* row = frame.ptr<std::uint8_t>(y);
        row[2 * x + 1] = 200;                // Y of pixel x
        row[2 * x + 8] = 200;                // U of the pair two pairs on (pixels x + 4, x + 5)
        const cv::Mat& out = d.apply(frame, PixelFormat::Uyvy, f.geometry().spans());
        QVERIFY(d.lastBlurred());
        const std::uint8_t* o = out.ptr<std::uint8_t>(y);
        const std::uint8_t* above = out.ptr<std::uint8_t>(y - 1);
        const std::uint8_t* below = out.ptr<std::uint8_t>(y + 1);
        QCOMPARE(int(o[2 * x + 1]), 200);
        QCOMPARE(int(o[2 * x + 3]), 100);
        QCOMPARE(int(above[2 * x + 1]), 100);
        QVERIFY(o[2 * x + 8] > 150 && o[2 * x + 8] < 200);
        QVERIFY(above[2 * x + 8] > 140);
        QCOMPARE(above[2 * x + 8], below[2 * x + 8]);
        QVERIFY(o[2 * x + 4] > 128 && o[2 * x + 4] < above[2 * x + 8]);
        QCOMPARE(o[2 * x + 4], o[2 * x + 12]);
        QCOMPARE(int(o[2 * x]), 128);       // two pairs away: untouched
        QCOMPARE(int(o[2 * x + 6]), 128);   // the V values beside it
        QCOMPARE(int(o[2 * x + 10]), 128);
        QCOMPARE(int(o[2 * x + 9]), 100);   // its pair's Y
        QCOMPARE(int(o[2 * x + 11]), 100);
    }

    void blurKeepsFlatAndSpreadsAPointEvenly()
    {
        Config c;
        c.denoise.aboveNoise = 0.001;  // blur anything with the slightest texture
        const FrontEnd f(c);
        FrameDenoiser d(c.denoise);
        cv::Mat frame = greenField(c);
        frame.at<cv::Vec3b>(0, 0) = cv::Vec3b(41, 141, 41);  // texture for the estimate (outside the ring)
        const cv::Point p(470, 240);  // 150 px from the robot centre, in the ring
        frame.at<cv::Vec3b>(p) = cv::Vec3b(40, 255, 40);
        const cv::Mat& out = d.apply(frame, PixelFormat::Bgr8, f.geometry().spans());
        QVERIFY(d.lastBlurred());
        // Flat stays flat, to the borders.
        QCOMPARE(out.at<cv::Vec3b>(479, 639), cv::Vec3b(40, 140, 40));
        QCOMPARE(out.at<cv::Vec3b>(100, 100), cv::Vec3b(40, 140, 40));
        // The point's excess (115) spreads symmetrically: centre > edge neighbours > corners, and
        // the 3x3 sum keeps it.
        auto g = [&](int dx, int dy) { return int(out.at<cv::Vec3b>(p + cv::Point(dx, dy))[1]) - 140; };
        QCOMPARE(g(-1, 0), g(1, 0));
        QCOMPARE(g(0, -1), g(0, 1));
        QCOMPARE(g(-1, 0), g(0, 1));
        QCOMPARE(g(-1, -1), g(1, 1));
        QVERIFY(g(0, 0) > g(1, 0) && g(1, 0) > g(1, 1) && g(1, 1) > 0);
        int sum = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) sum += g(dx, dy);
        QVERIFY2(std::abs(sum - 115) <= 4, qPrintable(QString("sum %1").arg(sum)));
        QCOMPARE(out.at<cv::Vec3b>(p + cv::Point(2, 0)), cv::Vec3b(40, 140, 40));
    }

    void pipelineSegmentsTheBlurredFrame()
    {
        Config c;
        const cv::Mat noisy = noisyField(c, 30.0);
        PipelineResult on;
        Pipeline(c).process(noisy, PixelFormat::Bgr8, on);
        QVERIFY(on.denoised);
        QVERIFY(on.frameNoise > c.denoise.aboveNoise);

        // The classes are those of the blurred frame.
        FrontEnd f(c);
        FrameDenoiser d(c.denoise);
        cv::Mat classes, binary, edges;
        f.process(d.apply(noisy, PixelFormat::Bgr8, f.geometry().spans()), PixelFormat::Bgr8, classes, binary, edges);
        QCOMPARE(cv::countNonZero(classes != on.classes), 0);

        // A UYVY frame: the pipeline segments its blurred copy too.
        const cv::Mat noisyUyvy = toUyvy(noisy);
        PipelineResult uyvy;
        Pipeline(c).process(noisyUyvy, PixelFormat::Uyvy, uyvy);
        QVERIFY(uyvy.denoised);
        f.process(d.apply(noisyUyvy, PixelFormat::Uyvy, f.geometry().spans()), PixelFormat::Uyvy, classes, binary, edges);
        QCOMPARE(cv::countNonZero(classes != uyvy.classes), 0);

        c.denoise.aboveNoise = 0.0;
        PipelineResult off;
        Pipeline(c).process(noisy, PixelFormat::Bgr8, off);
        QVERIFY(!off.denoised);
        // Noise throws carpet pixels out of the field classes; the blurred frame keeps fewer out.
        const double before = nonFieldShare(f, off.classes);
        const double after = nonFieldShare(f, on.classes);
        QVERIFY2(before > 0.01 && after < 0.5 * before, qPrintable(QString("non-field %1 -> %2").arg(before).arg(after)));
    }
};

QTEST_APPLESS_MAIN(FrameDenoiseTest)
#include "core_frame_denoise_test.moc"
