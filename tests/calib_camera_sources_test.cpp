// The real camera sources on a machine without cameras (CI, this one): libdc1394 and V4L2 say
// clearly that there is no device, never crash or hang; the catalog says none were found and
// refuses unknown sources. And the UYVY -> BGR conversion the libdc1394 source uses: the same
// as libdc1394's own dc1394_convert_to_RGB8 (within its integer rounding), and deliberately not
// cv::cvtColor(COLOR_YUV2BGR_UYVY), which assumes video-range YUV (docs/cameras.md).
#include "calib/camera/CameraCatalog.h"
#include "calib/camera/Dc1394Camera.h"
#include "calib/camera/V4l2Camera.h"
#include "core/ColorLut.h"

#include <dc1394/conversions.h>
#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <filesystem>

using namespace omnitune;

namespace {

// Every Y with a spread of U and V: 256 rows of pixel pairs.
cv::Mat uyvyGrid()
{
    cv::Mat uyvy(256, 2 * 86 * 86, CV_8UC2);
    for (int y = 0; y < 256; ++y) {
        uchar* p = uyvy.ptr<uchar>(y);
        for (int u = 0; u < 86; ++u)
            for (int v = 0; v < 86; ++v, p += 4) {
                p[0] = uchar(u * 3);
                p[1] = uchar(y);
                p[2] = uchar(v * 3);
                p[3] = uchar(255 - y);
            }
    }
    return uyvy;
}

bool hasCaptureDevice() { return !listV4l2Cameras().cameras.empty(); }

}  // namespace

class CameraSourcesTest : public QObject {
    Q_OBJECT

private slots:
    void uyvyMatchesLibdc1394()
    {
        cv::Mat uyvy = uyvyGrid();
        cv::Mat ours;
        convertUyvyToBgr(uyvy, ours);
        cv::Mat rgb(uyvy.size(), CV_8UC3);
        QCOMPARE(int(dc1394_convert_to_RGB8(uyvy.data, rgb.data, uint32_t(uyvy.cols), uint32_t(uyvy.rows),
                                            DC1394_BYTE_ORDER_UYVY, DC1394_COLOR_CODING_YUV422, 8)),
                 int(DC1394_SUCCESS));
        cv::Mat theirs;
        cv::cvtColor(rgb, theirs, cv::COLOR_RGB2BGR);
        // libdc1394 uses integer shifts (x * 1436 >> 10 ...), we round: at most one level apart.
        QVERIFY2(cv::norm(ours, theirs, cv::NORM_INF) <= 1.0,
                 qPrintable(QString::number(cv::norm(ours, theirs, cv::NORM_INF))));
    }

    // The documented difference: cvtColor reads Y as video range (16 black, 235 white) and
    // stretches it; an IIDC camera's Y is full range, which libdc1394 and we keep.
    void uyvyDiffersFromCvtColorAsDocumented()
    {
        cv::Mat grey(1, 2, CV_8UC2);
        const auto greyLevel = [&](int y) {
            uchar* p = grey.ptr<uchar>(0);
            p[0] = 128, p[1] = uchar(y), p[2] = 128, p[3] = uchar(y);
            cv::Mat ours, cv;
            convertUyvyToBgr(grey, ours);
            cv::cvtColor(grey, cv, cv::COLOR_YUV2BGR_UYVY);
            return std::make_pair(int(ours.at<cv::Vec3b>(0, 0)[1]), int(cv.at<cv::Vec3b>(0, 0)[1]));
        };
        QCOMPARE(greyLevel(235).first, 235);  // full range: grey stays itself
        QCOMPARE(greyLevel(235).second, 255); // video range: 235 is already white
        QCOMPARE(greyLevel(16).first, 16);
        QCOMPARE(greyLevel(16).second, 0);
        QVERIFY(std::abs(greyLevel(128).second - int(std::lround(1.164 * (128 - 16)))) <= 1);
    }

    void guidsRoundTrip()
    {
        QCOMPARE(formatGuid(0x00b09d0100a01a9aull), std::string("0x00b09d0100a01a9a"));
        QCOMPARE(parseGuid("0x00b09d0100a01a9a"), std::optional<std::uint64_t>(0x00b09d0100a01a9aull));
        QCOMPARE(parseGuid("b09d0100a01a9a"), std::optional<std::uint64_t>(0xb09d0100a01a9aull));
        QVERIFY(!parseGuid("0x"));
        QVERIFY(!parseGuid("camera1"));
        QVERIFY(!parseGuid("0x1234567890abcdef0"));
    }

    void dc1394WithoutCameraSaysSo()
    {
        if (!listDc1394Cameras().cameras.empty()) QSKIP("an IIDC camera is connected");
        Dc1394Camera cam;
        const auto err = cam.open();
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::NoDevice);
        QVERIFY2(err->message.find("dc1394") != std::string::npos &&
                     (err->message.find("no FireWire bus") != std::string::npos ||
                      err->message.find("no camera") != std::string::npos),
                 err->message.c_str());
        QVERIFY(!cam.isOpen());
        Frame f;
        QCOMPARE(cam.grab(f)->kind, CameraErrorKind::NotStarted);
        QCOMPARE(cam.setFeature(CameraFeatureId::Exposure, 1)->kind, CameraErrorKind::NotStarted);
        QVERIFY(cam.features().empty());
        cam.close();  // twice is harmless
        cam.close();

        Dc1394Camera byGuid(0x00b09d0100a01a9aull);
        const auto err2 = byGuid.open();
        QVERIFY(err2 && err2->kind == CameraErrorKind::NoDevice);
    }

    void v4l2WithoutDeviceSaysSo()
    {
        const std::string missing = "/dev/video-omnitune-none";
        QVERIFY(!std::filesystem::exists(missing));
        V4l2Camera cam(missing);
        const auto err = cam.open();
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::NoDevice);
        QVERIFY2(err->message.find(missing) != std::string::npos, err->message.c_str());
        Frame f;
        QCOMPARE(cam.grab(f)->kind, CameraErrorKind::NotStarted);

        // A file that is not a V4L2 device.
        V4l2Camera notDevice("/dev/null");
        const auto err2 = notDevice.open();
        QVERIFY(err2);
        QCOMPARE(err2->kind, CameraErrorKind::NoDevice);
        QVERIFY2(err2->message.find("not a V4L2 device") != std::string::npos, err2->message.c_str());

        if (hasCaptureDevice()) QSKIP("a V4L2 capture device is connected");
        V4l2Camera first;
        const auto err3 = first.open();
        QVERIFY(err3 && err3->kind == CameraErrorKind::NoDevice);
    }

    void catalogSaysNoneFound()
    {
        const CameraScan scan = listCameras();
        if (!scan.cameras.empty()) QSKIP("a camera is connected");
        QVERIFY(scan.notes.size() >= 2);  // one per backend
        const CameraOpen first = openCamera("");
        QVERIFY(!first.ok());
        QCOMPARE(first.error->kind, CameraErrorKind::NoDevice);
        QVERIFY2(first.error->message.find("no camera found") != std::string::npos, first.error->message.c_str());
        QVERIFY2(first.error->message.find("--source simulated") != std::string::npos, first.error->message.c_str());
    }

    void catalogOpensSimulatedAndRefusesUnknown()
    {
        SimulatedCameraOptions o;
        o.poses = 1;
        const CameraOpen sim = openCamera("simulated", 25.0, o);
        QVERIFY(sim.ok());
        QVERIFY(sim.camera->isOpen());
        QVERIFY(!sim.camera->start());
        Frame a, b;
        QVERIFY(!sim.camera->grab(a) && !sim.camera->grab(b));
        QCOMPARE(b.timestampS - a.timestampS, 1 / 25.0);

        const CameraOpen bad = openCamera("firewire");
        QVERIFY(!bad.ok());
        QVERIFY2(bad.error->message.find("unknown camera source 'firewire'") != std::string::npos, bad.error->message.c_str());
        const CameraOpen badGuid = openCamera("dc1394:camera1");
        QVERIFY(!badGuid.ok());
        QVERIFY2(badGuid.error->message.find("not a GUID") != std::string::npos, badGuid.error->message.c_str());
    }
};

QTEST_GUILESS_MAIN(CameraSourcesTest)
#include "calib_camera_sources_test.moc"
