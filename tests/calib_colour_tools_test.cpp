// The editor's Qt-free colour tools: boxes from samples (hue on the circle, outliers ignored),
// growing and cutting boxes, the sampled area of a gesture, masked samples counted, the magic
// wand, class shares with overlaps, and the H-S / V histograms.
#include "calib/colour/BoxFit.h"
#include "calib/colour/ClassSampling.h"
#include "calib/colour/ClassShares.h"
#include "calib/colour/ClassView.h"
#include "calib/colour/ColourSamples.h"
#include "calib/colour/HsvHistogram.h"
#include "calib/colour/HsvImage.h"
#include "calib/colour/HueArc.h"
#include "calib/colour/MagicWand.h"
#include "calib/colour/SampleArea.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

Q_DECLARE_METATYPE(std::vector<int>)

namespace {

std::vector<Hsv> huesAt(const std::vector<int>& hues, int s = 200, int v = 200)
{
    std::vector<Hsv> out;
    for (int h : hues) out.push_back({h, s, v});
    return out;
}

HsvRange box(int h0, int h1, int s0 = 0, int s1 = 255, int v0 = 0, int v1 = 255)
{
    HsvRange r;
    r.hMin = h0;
    r.hMax = h1;
    r.sMin = s0;
    r.sMax = s1;
    r.vMin = v0;
    r.vMax = v1;
    return r;
}

}  // namespace

class ColourToolsTest : public QObject {
    Q_OBJECT
private slots:
    void fitHue_data()
    {
        QTest::addColumn<std::vector<int>>("hues");
        QTest::addColumn<int>("hMin");
        QTest::addColumn<int>("hMax");
        QTest::newRow("orange, no wrap") << std::vector<int>{10, 12, 15, 11} << 10 << 15;
        QTest::newRow("red wraps through 0") << std::vector<int>{170, 175, 179, 0, 5, 10} << 170 << 10;
        QTest::newRow("red mostly above 0") << std::vector<int>{178, 179, 1} << 178 << 1;
        QTest::newRow("one click") << std::vector<int>{42} << 42 << 42;
        QTest::newRow("grey: hue is noise") << std::vector<int>{0, 30, 60, 90, 120, 150} << 0 << 179;
    }
    void fitHue()
    {
        QFETCH(std::vector<int>, hues);
        QFETCH(int, hMin);
        QFETCH(int, hMax);
        const auto b = fitBox(huesAt(hues));
        QVERIFY(b.has_value());
        QCOMPARE(b->hMin, hMin);
        QCOMPARE(b->hMax, hMax);
        for (int h : hues) QVERIFY(b->containsHue(h));
    }

    void fitIgnoresOutliersPerChannel()
    {
        // 200 samples of S 100..199 plus two strays at S 5 and 250; 1 % = 2 samples per end.
        std::vector<Hsv> samples;
        for (int i = 0; i < 200; ++i) samples.push_back({30 + i % 3, 100 + i % 100, 120});
        samples.push_back({30, 5, 120});
        samples.push_back({30, 250, 120});
        BoxFitOptions o;
        o.outlierPct = 1.0;
        const auto b = fitBox(samples, o);
        QVERIFY(b.has_value());
        QVERIFY(b->sMin >= 100);
        QVERIFY(b->sMax <= 199);
        o.outlierPct = 0.0;
        const auto all = fitBox(samples, o);
        QCOMPARE(all->sMin, 5);
        QCOMPARE(all->sMax, 250);
        QVERIFY(!fitBox({}, o).has_value());
    }

    void growUnitesArcsTheShortWay()
    {
        // A red box 170..5 grown by hues 8..10 stays wrapped: 170..10, not 5..170.
        const HsvRange grown = growBox(box(170, 5, 100, 200, 100, 200), huesAt({8, 9, 10}, 220, 90));
        QCOMPARE(grown.hMin, 170);
        QCOMPARE(grown.hMax, 10);
        QCOMPARE(grown.sMax, 220);
        QCOMPARE(grown.vMin, 90);
        QCOMPARE(grown.sMin, 100);
        // A disabled box is empty: the samples' box replaces it.
        HsvRange off = box(0, 179);
        off.enabled = false;
        const HsvRange fresh = growBox(off, huesAt({50, 52}));
        QVERIFY(fresh.enabled);
        QCOMPARE(fresh.hMin, 50);
        QCOMPARE(fresh.hMax, 52);
    }

    void uniteArcs()
    {
        QCOMPARE(unite({170, 10}, {5, 3}).start, 170);  // 170..179 + 5..7 -> 170..7
        QCOMPARE(unite({170, 10}, {5, 3}).length, 18);
        QCOMPARE(unite({0, 100}, {90, 100}).length, 180);  // together every hue
        QCOMPARE(unite({40, 5}, {40, 5}).length, 5);
    }

    void cutKeepsMostVolume()
    {
        // Green 35..85 with S 60..255: samples at S 60..80 (a pale patch) are cut from below in S,
        // which costs far less than any hue or V cut.
        const HsvRange green = box(35, 85, 60, 255, 40, 255);
        std::vector<Hsv> pale;
        for (int s = 60; s <= 80; ++s) pale.push_back({40 + s % 40, s, 100 + s});
        const BoxCut c = cutBox(green, pale);
        QVERIFY(c.changed);
        QVERIFY(c.box.has_value());
        QCOMPARE(c.box->sMin, 81);
        QCOMPARE(c.box->hMin, 35);
        QCOMPARE(c.box->hMax, 85);
        QCOMPARE(c.removedSamples, int(pale.size()));
        for (const Hsv& p : pale) QVERIFY(!c.box->contains(p.h, p.s, p.v));

        // Hues at the arc's end: the hue cut wins and keeps the wrap.
        const BoxCut r = cutBox(box(170, 20), huesAt({15, 18, 20}, 128, 128));
        QVERIFY(r.box.has_value());
        QCOMPARE(r.box->hMin, 170);
        QCOMPARE(r.box->hMax, 14);

        // A full-hue box cut by hue keeps the hues outside the samples' arc.
        const BoxCut f = cutBox(box(0, 179, 0, 255, 0, 255), huesAt({10, 12}, 128, 128));
        QVERIFY(f.box.has_value());
        QVERIFY(!f.box->containsHue(11));
        QVERIFY(f.box->containsHue(100));

        // Samples outside: unchanged; samples filling the box: nothing left.
        QVERIFY(!cutBox(green, huesAt({120})).changed);
        const BoxCut gone = cutBox(box(50, 50, 10, 10, 10, 10), {{50, 10, 10}});
        QVERIFY(gone.changed);
        QVERIFY(!gone.box.has_value());
    }

    void classSampling()
    {
        // Adding to a class without boxes makes one; adding again grows the chosen box.
        std::vector<HsvRange> boxes;
        SampleEdit e = addSamples(boxes, 0, huesAt({20, 22}));
        QVERIFY(e.changed);
        QCOMPARE(int(boxes.size()), 1);
        e = addSamples(boxes, 0, huesAt({25}));
        QCOMPARE(boxes[0].hMax, 25);
        QVERIFY(!addSamples(boxes, 0, huesAt({21})).changed);  // already covered
        e = addSamples(boxes, -1, huesAt({100}));               // "new box"
        QCOMPARE(e.box, 1);
        QCOMPARE(int(boxes.size()), 2);

        // Removing cuts the boxes that hold samples and drops a box with nothing left.
        e = removeSamples(boxes, huesAt({100}));
        QVERIFY(e.changed);
        QCOMPARE(e.boxesDropped, 1);
        QCOMPARE(e.samplesOut, 1);
        QCOMPARE(int(boxes.size()), 1);
        // Nothing left: the last box stays, switched off, and the next samples make it anew.
        std::vector<HsvRange> one = {box(50, 50, 200, 200, 200, 200)};
        e = removeSamples(one, huesAt({50}));
        QVERIFY(e.lastBoxOff);
        QVERIFY(e.changed);
        QCOMPARE(e.samplesOut, 1);
        QCOMPARE(int(one.size()), 1);
        QVERIFY(!one[0].enabled);
        addSamples(one, 0, huesAt({90}));
        QVERIFY(one[0].enabled);
        QCOMPARE(one[0].hMin, 90);
    }

    void gestureAreas()
    {
        const cv::Size frame(20, 10);
        QCOMPARE(discPixels({5, 5}, 0, frame).size(), std::size_t(1));
        QCOMPARE(discPixels({5, 5}, 2, frame).size(), std::size_t(13));  // the 5x5 disc of radius 2
        QCOMPARE(discPixels({0, 0}, 2, frame).size(), std::size_t(6));   // clipped to the frame
        const auto stroke = strokePixels({{2, 5}, {12, 5}}, 1, frame);
        QCOMPARE(stroke.size(), std::size_t(11 * 3 + 2));  // 11 columns x 3 rows and the discs' ends, once each
        QCOMPARE(rectPixels({3, 4}, {1, 2}, frame).size(), std::size_t(9));
        QCOMPARE(rectPixels({18, 8}, {30, 30}, frame).size(), std::size_t(4));
    }

    void maskedSamplesAreCounted()
    {
        cv::Mat frame(10, 10, CV_8UC3, cv::Scalar(0, 200, 0));
        cv::Mat used(10, 10, CV_8UC1, cv::Scalar(255));
        used(cv::Rect(0, 0, 5, 10)).setTo(0);
        const ColourSamples s = sampleColours(frame, PixelFormat::Bgr8, used, rectPixels({0, 0}, {9, 0}, frame.size()));
        QCOMPARE(int(s.hsv.size()), 5);
        QCOMPARE(s.masked, 5);
        QCOMPARE(s.hsv.front().h, 60);  // pure green
        ColourSamples sum = s;
        sum.append(s);
        QCOMPARE(sum.masked, 10);
        QCOMPARE(int(sum.hsv.size()), 10);
    }

    void uyvyFramesGiveTheSameColours()
    {
        cv::Mat bgr(4, 4, CV_8UC3, cv::Scalar(20, 110, 240));
        cv::Mat uyvy(4, 4, CV_8UC2, cv::Scalar(90, 128));
        const cv::Mat hsv = hsvImage(uyvy, PixelFormat::Uyvy);
        const ColourSamples s = sampleColours(uyvy, PixelFormat::Uyvy, cv::Mat(), {{1, 1}});
        QCOMPARE(s.hsv.front().h, int(hsv.at<cv::Vec3b>(1, 1)[0]));
        QCOMPARE(s.hsv.front().s, int(hsv.at<cv::Vec3b>(1, 1)[1]));
        QCOMPARE(s.hsv.front().v, int(hsv.at<cv::Vec3b>(1, 1)[2]));
        QCOMPARE(hsvImage(bgr, PixelFormat::Bgr8).at<cv::Vec3b>(0, 0)[0], std::uint8_t(12));  // orange
    }

    void wandStaysInItsColourAndArea()
    {
        // Carpet with an orange disc whose right half is masked, and a second orange disc apart.
        cv::Mat frame(60, 100, CV_8UC3, cv::Scalar(40, 140, 30));
        cv::circle(frame, {25, 30}, 10, cv::Scalar(20, 110, 240), cv::FILLED);
        cv::circle(frame, {75, 30}, 10, cv::Scalar(20, 110, 240), cv::FILLED);
        cv::Mat used(frame.size(), CV_8UC1, cv::Scalar(255));
        used(cv::Rect(26, 0, 10, 60)).setTo(0);
        const cv::Mat hsv = hsvImage(frame, PixelFormat::Bgr8);
        const auto region = magicWand(hsv, used, {20, 30}, WandTolerance{});
        cv::Mat disc(frame.size(), CV_8UC1, cv::Scalar(0));
        cv::circle(disc, {25, 30}, 10, cv::Scalar(255), cv::FILLED);
        const int expected = cv::countNonZero(disc & used);
        QCOMPARE(int(region.size()), expected);
        for (const cv::Point& p : region) {
            QVERIFY(disc.at<std::uint8_t>(p) != 0);
            QVERIFY(used.at<std::uint8_t>(p) != 0);
        }
        QVERIFY(magicWand(hsv, used, {30, 30}, WandTolerance{}).empty());  // seed masked
        WandTolerance capped;
        capped.maxPixels = 10;
        QCOMPARE(int(magicWand(hsv, used, {5, 5}, capped).size()), 10);
    }

    void wandHueWrapsThroughZero()
    {
        // Two reds either side of hue 0 (H 178 and 2) form one region.
        cv::Mat hsv(1, 4, CV_8UC3);
        hsv.at<cv::Vec3b>(0, 0) = {178, 200, 200};
        hsv.at<cv::Vec3b>(0, 1) = {2, 200, 200};
        hsv.at<cv::Vec3b>(0, 2) = {3, 210, 190};
        hsv.at<cv::Vec3b>(0, 3) = {60, 200, 200};
        QCOMPARE(int(magicWand(hsv, cv::Mat(), {0, 0}, WandTolerance{}).size()), 3);
    }

    void sharesAndOverlaps()
    {
        // 4 pixels: green, yellow-green (claimed by green and yellow), yellow, grey.
        cv::Mat hsv(1, 5, CV_8UC3);
        hsv.at<cv::Vec3b>(0, 0) = {60, 200, 200};
        hsv.at<cv::Vec3b>(0, 1) = {32, 200, 200};
        hsv.at<cv::Vec3b>(0, 2) = {25, 200, 200};
        hsv.at<cv::Vec3b>(0, 3) = {0, 0, 128};
        hsv.at<cv::Vec3b>(0, 4) = {60, 200, 200};
        cv::Mat used(1, 5, CV_8UC1, cv::Scalar(255));
        used.at<std::uint8_t>(0, 4) = 0;  // not processed: not counted
        const ClassBoxes classes = {{box(30, 90, 50, 255, 40, 255)}, {box(20, 35, 50, 255, 40, 255)}};
        const ClassShares s = classShares(hsv, used, classes);
        QCOMPARE(s.processed, 4);
        QCOMPARE(s.counts[0], 2);  // green wins the overlap: first in priority
        QCOMPARE(s.counts[1], 1);
        QCOMPARE(s.unclassified, 1);
        QCOMPARE(s.overlapCount, 1);
        QCOMPARE(int(s.overlap.at<std::uint8_t>(0, 1)), 255);
        QCOMPARE(s.pct(s.unclassified), 25.0);
        // Priority swapped: the overlap goes to yellow.
        const ClassShares swapped = classShares(hsv, used, {classes[1], classes[0]});
        QCOMPARE(swapped.counts[0], 2);
        // A class of two boxes claims both.
        const ClassShares two = classShares(hsv, used, {{box(55, 65), box(0, 5, 0, 10)}});
        QCOMPARE(two.counts[0], 2);
        // The shares as the pipeline segmented the frame (relative black, LUT bits): the
        // processed pixels' ids count, the overlap stays the boxes'.
        ClassShares seen = s;
        cv::Mat ids(1, 5, CV_8UC1, cv::Scalar(2));
        ids.at<std::uint8_t>(0, 0) = 0;
        countSegmented(seen, ids, used);
        QCOMPARE(seen.processed, 4);
        QCOMPARE(seen.counts[0], 0);
        QCOMPARE(seen.counts[1], 3);
        QCOMPARE(seen.unclassified, 1);
        QCOMPARE(seen.overlapCount, 1);
    }

    void classViewDimsAndFlags()
    {
        cv::Mat segmented(2, 4, CV_8UC3, cv::Scalar(0, 160, 0));
        cv::Mat classes(2, 4, CV_8UC1, cv::Scalar(3));
        classes.at<std::uint8_t>(0, 1) = 5;
        cv::Mat overlap(2, 4, CV_8UC1, cv::Scalar(0));
        overlap.at<std::uint8_t>(1, 3) = 255;
        const cv::Mat all = classView(segmented, classes, overlap, {});
        QCOMPARE(cv::countNonZero(all.reshape(1) != segmented.reshape(1)), 0);  // nothing asked: unchanged
        ClassViewOptions only;
        only.onlyClass = 5;
        const cv::Mat one = classView(segmented, classes, overlap, only);
        QCOMPARE(one.at<cv::Vec3b>(0, 1), cv::Vec3b(0, 160, 0));  // the class shown as it is
        QCOMPARE(one.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 40, 0));   // the others dimmed
        ClassViewOptions flag;
        flag.flagOverlaps = true;
        const cv::Vec3b flagged = classView(segmented, classes, overlap, flag).at<cv::Vec3b>(1, 3);
        QVERIFY(flagged == cv::Vec3b(255, 255, 255) || flagged == cv::Vec3b(0, 0, 255));
    }

    void histograms()
    {
        cv::Mat hsv(2, 3, CV_8UC3, cv::Scalar(60, 200, 90));
        hsv.at<cv::Vec3b>(1, 2) = {10, 5, 250};
        cv::Mat used(2, 3, CV_8UC1, cv::Scalar(255));
        used.at<std::uint8_t>(0, 0) = 0;
        const HsvHistogram h = hsvHistogram(hsv, used);
        QCOMPARE(h.hs.rows, 180);
        QCOMPARE(h.hs.cols, 256);
        QCOMPARE(h.pixels, 5);
        QCOMPARE(h.hs.at<int>(60, 200), 4);
        QCOMPARE(h.hs.at<int>(10, 5), 1);
        QCOMPARE(h.v[90], 4);
        QCOMPARE(h.v[250], 1);
        const cv::Mat plane = hsPlaneImage(h);
        QCOMPARE(plane.size(), cv::Size(180, 256));
        QCOMPARE(plane.at<cv::Vec3b>(255 - 100, 100), cv::Vec3b(0, 0, 0));  // no pixel there
        const cv::Vec3b green = plane.at<cv::Vec3b>(255 - 200, 60);         // the most common colour, full bright
        QCOMPARE(int(green[1]), 255);
        QVERIFY(green[0] < 100 && green[2] < 100);
    }
};

QTEST_GUILESS_MAIN(ColourToolsTest)
#include "calib_colour_tools_test.moc"
