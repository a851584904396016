// The camera interface (calib/camera/Camera.h) on the simulated camera: the open / start /
// grab / stop / close cycle, features with ranges, typed errors, read-back, the sensor model
// (exposure, gain, brightness, white balance, clipping, noise), the delay before a setting
// takes effect, start states, determinism; and the FrameSource adapter, held to the same
// forward-reading contract as a recorded session.
#include "calib/camera/CameraFrameSource.h"
#include "calib/camera/SimulatedCamera.h"
#include "calib/source/FrameSourceFactory.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

namespace {

// A small, quick camera for most checks (the optics are traced once per size).
SimulatedCameraOptions smallOptions(SimulatedStart start = SimulatedStart::Good)
{
    SimulatedCameraOptions o;
    o.start = start;
    o.poses = 2;
    return o;
}

Frame grabOne(Camera& cam)
{
    Frame f;
    const auto err = cam.grab(f);
    if (err) qWarning("%s", err->message.c_str());
    return f;
}

double meanGrey(const cv::Mat& bgr, cv::Rect r = {})
{
    cv::Mat grey;
    cv::cvtColor(r.empty() ? bgr : bgr(r), grey, cv::COLOR_BGR2GRAY);
    return cv::mean(grey)[0];
}

// The forward-reading contract every FrameSource keeps: kNext gives frames 0, 1, 2 ... of
// frameSize() as BGR, and a failed seek on a non-seekable source says so.
void checkForwardContract(FrameSource& source, int frames)
{
    for (int i = 0; i < frames; ++i) {
        Frame f;
        const auto err = source.read(FrameSource::kNext, f);
        QVERIFY2(!err, err ? err->message.c_str() : "");
        QCOMPARE(f.index, i);
        QCOMPARE(f.image.type(), CV_8UC3);
        QCOMPARE(f.image.size(), source.frameSize());
        QVERIFY(f.camera.has_value());
    }
    QCOMPARE(source.nextIndex(), frames);
    if (!source.isSeekable()) {
        Frame f;
        const auto err = source.read(0, f);
        QVERIFY(err);
        QCOMPARE(err->kind, FrameErrorKind::NotSeekable);
    }
}

}  // namespace

class CameraTest : public QObject {
    Q_OBJECT

private slots:
    void lifecycleAndErrorsBeforeStart()
    {
        SimulatedCamera cam(smallOptions());
        QVERIFY(!cam.isOpen());
        QVERIFY(cam.frameSize().empty());
        Frame f;
        auto err = cam.grab(f);
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::NotStarted);
        err = cam.setFeature(CameraFeatureId::Gain, 10);
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::NotStarted);

        QVERIFY(!cam.open());
        QCOMPARE(cam.frameSize(), cv::Size(640, 480));
        err = cam.grab(f);
        QVERIFY(err && err->kind == CameraErrorKind::NotStarted);
        QVERIFY(!cam.start());
        for (int i = 0; i < 3; ++i) {
            err = cam.grab(f);
            QVERIFY(!err);
            QCOMPARE(f.index, i);
            QCOMPARE(f.timestampS, i / 30.0);
            QCOMPARE(f.image.size(), cv::Size(640, 480));
        }
        cam.stop();
        QVERIFY(cam.grab(f));
        cam.close();
        QVERIFY(!cam.isOpen());
    }

    void featuresHaveRangesAndReadBack()
    {
        SimulatedCamera cam(smallOptions());
        QVERIFY(!cam.open());
        const auto features = cam.features();
        const CameraFeature* exposure = findCameraFeature(features, CameraFeatureId::Exposure);
        QVERIFY(exposure);
        QCOMPARE(exposure->min, 0);
        QCOMPARE(exposure->max, 4095);
        QCOMPARE(exposure->value, CameraSettings{}.exposure);
        QVERIFY(findCameraFeature(features, CameraFeatureId::WhiteBalanceBlue));
        QVERIFY(findCameraFeature(features, CameraFeatureId::WhiteBalanceRed));

        QVERIFY(!cam.setFeature(CameraFeatureId::Exposure, 410));
        CameraFeature back;
        QVERIFY(!cam.readFeature(CameraFeatureId::Exposure, back));
        QCOMPARE(back.value, 410);

        auto err = cam.setFeature(CameraFeatureId::Gain, 1024);
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::ValueOutOfRange);
        QVERIFY2(err->message.find("gain 1024 is outside its range 0..1023") != std::string::npos, err->message.c_str());
        QVERIFY(!cam.readFeature(CameraFeatureId::Gain, back));
        QCOMPARE(back.value, CameraSettings{}.gain);  // the refused write changed nothing

        err = cam.setFeature(CameraFeatureId::Gamma, 1);
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::FeatureUnsupported);
        QVERIFY2(err->message.find("simulated camera") != std::string::npos, err->message.c_str());
        err = cam.setAuto(CameraFeatureId::Exposure, true);
        QVERIFY(err && err->kind == CameraErrorKind::FeatureUnsupported);
        QVERIFY(!cam.setAuto(CameraFeatureId::Exposure, false));  // "all auto off" always works
    }

    void featureNamesRoundTrip()
    {
        for (CameraFeatureId id : kAllCameraFeatures) QCOMPARE(parseCameraFeatureName(cameraFeatureName(id)), id);
        QCOMPARE(parseCameraFeatureName("wb_u"), CameraFeatureId::WhiteBalanceBlue);
        QCOMPARE(parseCameraFeatureName("wb_v"), CameraFeatureId::WhiteBalanceRed);
        QVERIFY(!parseCameraFeatureName("exposur"));
    }

    // A write shows 1 or 2 frames later, never in the very next frame and never later than 2.
    void settingTakesEffectAfterOneOrTwoFrames()
    {
        SimulatedCamera cam(smallOptions());
        QVERIFY(!cam.open() && !cam.start());
        grabOne(cam);
        bool sawDelay2 = false;
        for (int k = 0; k < 8; ++k) {
            const int value = 300 + 50 * (k + 1);
            QVERIFY(!cam.setFeature(CameraFeatureId::Exposure, value));
            const Frame a = grabOne(cam), b = grabOne(cam), c = grabOne(cam);
            QVERIFY(a.camera->exposure != value);
            QVERIFY(c.camera->exposure == value);
            if (b.camera->exposure != value) sawDelay2 = true;
        }
        QVERIFY(sawDelay2);
    }

    // Exposure and gain scale the image, brightness lifts black, white balance moves one
    // channel each, 255 clips, more gain more noise.
    void sensorActsLikeASensor()
    {
        SimulatedCameraOptions o = smallOptions();
        o.settingsDelay = false;
        SimulatedCamera cam(o);
        QVERIFY(!cam.open() && !cam.start());
        // Without black offset, twice the exposure is twice the signal (carpet, far from clipping).
        QVERIFY(!cam.setFeature(CameraFeatureId::Brightness, 0));
        QVERIFY(!cam.setFeature(CameraFeatureId::Exposure, 150));
        const Frame base = grabOne(cam);
        const double mid = meanGrey(base.image, cv::Rect(200, 300, 60, 60));

        QVERIFY(!cam.setFeature(CameraFeatureId::Exposure, 300));
        const Frame doubled = grabOne(cam);
        const double midDoubled = meanGrey(doubled.image, cv::Rect(200, 300, 60, 60));
        QVERIFY2(std::abs(midDoubled / mid - 2.0) < 0.15, qPrintable(QString("%1 -> %2").arg(mid).arg(midDoubled)));

        QVERIFY(!cam.setFeature(CameraFeatureId::Exposure, 4095));
        QVERIFY(!cam.setFeature(CameraFeatureId::Gain, 1023));
        const Frame clipped = grabOne(cam);
        double maxV = 0;
        cv::minMaxLoc(clipped.image.reshape(1), nullptr, &maxV);
        QCOMPARE(maxV, 255.0);
        QVERIFY(meanGrey(clipped.image, cv::Rect(200, 300, 60, 60)) > 200);

        // Noise: spread over a flat card at low and high gain, same mean level.
        const cv::Rect card = o.blackCard;
        const auto cardSpread = [&](int exposure, int gain) {
            cam.setFeature(CameraFeatureId::Exposure, exposure);
            cam.setFeature(CameraFeatureId::Gain, gain);
            cam.setFeature(CameraFeatureId::Brightness, 640);
            cv::Mat grey;
            cv::cvtColor(grabOne(cam).image(card), grey, cv::COLOR_BGR2GRAY);
            cv::Scalar mean, sd;
            cv::meanStdDev(grey, mean, sd);
            return sd[0];
        };
        QVERIFY(cardSpread(300, 800) > 2 * cardSpread(1200, 0));

        QVERIFY(!cam.setFeature(CameraFeatureId::Exposure, 300));
        QVERIFY(!cam.setFeature(CameraFeatureId::Gain, 200));
        QVERIFY(!cam.setFeature(CameraFeatureId::Brightness, 0));
        const double black0 = meanGrey(grabOne(cam).image, o.blackCard);
        QVERIFY(!cam.setFeature(CameraFeatureId::Brightness, 480));
        const double black30 = meanGrey(grabOne(cam).image, o.blackCard);
        QVERIFY2(std::abs(black30 - black0 - 30) < 2, qPrintable(QString("%1 -> %2").arg(black0).arg(black30)));

        const cv::Scalar white0 = cv::mean(grabOne(cam).image(o.whiteCard));
        QVERIFY(!cam.setFeature(CameraFeatureId::WhiteBalanceBlue, 250));
        const cv::Scalar white1 = cv::mean(grabOne(cam).image(o.whiteCard));
        QVERIFY(white1[0] < 0.6 * white0[0]);        // blue halved
        QVERIFY(std::abs(white1[1] - white0[1]) < 2);  // green untouched
    }

    void startStatesAreBadlySet()
    {
        const auto frame = [](SimulatedStart s) {
            SimulatedCamera cam(smallOptions(s));
            cam.open();
            cam.start();
            return grabOne(cam).image;
        };
        const cv::Mat good = frame(SimulatedStart::Good), dark = frame(SimulatedStart::Dark),
                      bright = frame(SimulatedStart::Bright), tinted = frame(SimulatedStart::Tinted);
        const cv::Rect carpet(200, 300, 60, 60);
        QVERIFY(meanGrey(dark, carpet) < 0.3 * meanGrey(good, carpet));
        QVERIFY(meanGrey(bright, carpet) > 240);
        const cv::Scalar w = cv::mean(tinted(SimulatedCameraOptions{}.whiteCard));
        QVERIFY2(w[2] > 2 * w[0], "tinted: the white card is red, not white");
    }

    void sameSeedSameFramesOtherSeedOtherNoise()
    {
        const auto frames = [](unsigned seed) {
            SimulatedCameraOptions o = smallOptions();
            o.seed = seed;
            SimulatedCamera cam(o);
            cam.open();
            cam.start();
            grabOne(cam);
            cam.setFeature(CameraFeatureId::Gain, 400);
            std::vector<cv::Mat> out;
            for (int i = 0; i < 4; ++i) out.push_back(grabOne(cam).image);
            return out;
        };
        const auto a = frames(1), b = frames(1), c = frames(2);
        for (std::size_t i = 0; i < a.size(); ++i) QCOMPARE(cv::norm(a[i], b[i], cv::NORM_INF), 0.0);
        QVERIFY(cv::norm(a[0], c[0], cv::NORM_INF) > 0);
    }

    void tourMovesTheRobot()
    {
        SimulatedCameraOptions o = smallOptions();
        o.framesPerPose = 2;
        SimulatedCamera cam(o);
        cam.open();
        cam.start();
        const cv::Mat a = grabOne(cam).image, a2 = grabOne(cam).image, b = grabOne(cam).image;
        cv::Mat d1, d2;
        cv::absdiff(a, a2, d1);
        cv::absdiff(a, b, d2);
        QVERIFY(cv::mean(d2)[1] > 3 * cv::mean(d1)[1]);  // a new place differs by more than noise
    }

    void unplugIsReported()
    {
        SimulatedCamera cam(smallOptions());
        cam.open();
        cam.start();
        grabOne(cam);
        cam.simulateUnplug();
        Frame f;
        const auto err = cam.grab(f);
        QVERIFY(err);
        QCOMPARE(err->kind, CameraErrorKind::Unplugged);
        QVERIFY2(err->message.find("unplugged") != std::string::npos, err->message.c_str());
        QVERIFY(cam.setFeature(CameraFeatureId::Gain, 1)->kind == CameraErrorKind::Unplugged);
        // Reopening is the reconnect.
        QVERIFY(!cam.open() && !cam.start());
        QVERIFY(!cam.grab(f));
    }

    void frameSourceAdapterPlaysForward()
    {
        CameraFrameSource source(std::make_unique<SimulatedCamera>(smallOptions()));
        QVERIFY(!source.camera().open());
        QCOMPARE(source.frameCount(), -1);
        QVERIFY(!source.isSeekable());
        QVERIFY(source.description().find("simulated camera") != std::string::npos);
        checkForwardContract(source, 4);
        QCOMPARE(source.lastCameraIndex(), 3);
    }

    void frameSourceAdapterReportsUnplug()
    {
        auto cam = std::make_unique<SimulatedCamera>(smallOptions());
        SimulatedCamera* raw = cam.get();
        CameraFrameSource source(std::move(cam));
        QVERIFY(!raw->open());
        Frame f;
        QVERIFY(!source.read(FrameSource::kNext, f));
        raw->simulateUnplug();
        const auto err = source.read(FrameSource::kNext, f);
        QVERIFY(err);
        QCOMPARE(err->kind, FrameErrorKind::Device);
        QVERIFY(err->message.find("unplugged") != std::string::npos);
    }

    // The same forward contract holds for a recorded session, the source a camera replaces.
    void sessionSourceKeepsTheSameContract()
    {
        auto open = openFrameSource(OMNITUNE_SOURCE_DIR "/sessions/demo");
        QVERIFY2(open.ok(), open.error.c_str());
        checkForwardContract(*open.source, 4);
    }
};

QTEST_GUILESS_MAIN(CameraTest)
#include "calib_camera_test.moc"
