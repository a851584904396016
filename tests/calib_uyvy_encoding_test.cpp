// calib/sim/UyvyEncoding: rendered frames as an IIDC camera's YUV 4:2:2, so the evaluation can
// run the detector's UYVY path (omnitune-eval --pixel-format uyvy). It must invert core's
// yuvToBgr, and share each pair's colour the way a 4:2:2 camera does.
#include "calib/sim/UyvyEncoding.h"
#include "core/ColorLut.h"

#include <QtTest>

#include <cstdlib>

using namespace omnitune;

class UyvyEncodingTest : public QObject {
    Q_OBJECT

private slots:
    void roundTripsFlatColours()
    {
        const cv::Vec3b colours[] = {{40, 140, 40}, {255, 255, 255}, {0, 0, 0}, {0, 128, 255}, {100, 150, 35}, {32, 92, 30}};
        for (const cv::Vec3b& c : colours) {
            const cv::Mat bgr(4, 8, CV_8UC3, cv::Scalar(c[0], c[1], c[2]));
            cv::Mat uyvy, back;
            convertBgrToUyvy(bgr, uyvy);
            QCOMPARE(uyvy.type(), CV_8UC2);
            QCOMPARE(uyvy.size(), bgr.size());
            convertUyvyToBgr(uyvy, back);
            for (int k = 0; k < 3; ++k)
                QVERIFY2(std::abs(int(back.at<cv::Vec3b>(2, 5)[k]) - int(c[k])) <= 2,
                         qPrintable(QString("channel %1: %2 -> %3").arg(k).arg(c[k]).arg(back.at<cv::Vec3b>(2, 5)[k])));
        }
    }

    void pairsShareTheirColourAndKeepTheirLuma()
    {
        // A grey pixel beside a red one: each keeps its own Y, both get the pair's mean chroma.
        cv::Mat bgr(1, 2, CV_8UC3);
        bgr.at<cv::Vec3b>(0, 0) = cv::Vec3b(128, 128, 128);
        bgr.at<cv::Vec3b>(0, 1) = cv::Vec3b(0, 0, 255);
        cv::Mat uyvy;
        convertBgrToUyvy(bgr, uyvy);
        const std::uint8_t* p = uyvy.ptr<std::uint8_t>(0);
        QCOMPARE(int(p[1]), 128);                   // Y0: grey
        QVERIFY(std::abs(int(p[3]) - 76) <= 1);     // Y1: 0.299 x 255
        QVERIFY(std::abs(int(p[2]) - 192) <= 1);    // V: 128 + (255 - 76) / 1.402 / 2
        QVERIFY(std::abs(int(p[0]) - 107) <= 1);    // U: 128 + (0 - 76) / 1.772 / 2
    }
};

QTEST_APPLESS_MAIN(UyvyEncodingTest)
#include "calib_uyvy_encoding_test.moc"
