// Venue profiles (calib/colour/ColourProfile.h, ColourProfileDiff.h): a colour calibration saved
// under a name beside the config loads back identical and is listed; bad profiles are refused
// with the file named and nothing is written for an invalid one; the diff shows the classes side
// by side and the pixels of a demo frame that change class.
#include "calib/colour/ColourProfile.h"
#include "calib/colour/ColourProfileDiff.h"
#include "core/ConfigParser.h"

#include <opencv2/imgcodecs.hpp>

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

using namespace omnitune;

namespace {

ColourProfile venueProfile()
{
    ColourProfile p;
    p.name = "Venue field A";
    p.colors.blackVRatio = 0.4;
    p.colors.classes[2].boxes.push_back(HsvRange{true, 86, 98, 50, 255, 30, 255});  // cyan-green carpet corner
    p.colors.classes[std::size_t(ColorClass::Yellow) - 1].enabled = true;
    return p;
}

}  // namespace

class ColourProfileTest : public QObject {
    Q_OBJECT
private slots:
    void saveLoadAndList()
    {
        QTemporaryDir dir;
        const std::string folder = colourProfileFolder(dir.filePath("config.yml").toStdString());
        QCOMPARE(QString::fromStdString(folder), dir.filePath("colour-profiles"));
        QCOMPARE(*colourProfileFileName("Venue field A"), std::string("venue-field-a.yml"));
        QVERIFY(!colourProfileFileName("  ...  "));

        const ColourProfile venue = venueProfile();
        ColourProfile home;
        home.name = "home lab";
        const ColourProfileSave a = saveColourProfile(folder, venue);
        QVERIFY2(!a.error, a.error ? a.error->toString().c_str() : "");
        QVERIFY(!saveColourProfile(folder, home).error);
        QVERIFY(QFile::exists(QString::fromStdString(folder) + "/venue-field-a.yml"));
        QCOMPARE(QDir(QString::fromStdString(folder)).entryList(QDir::Files).size(), 2);  // no temporaries left

        const ColourProfileLoad back = loadColourProfile(a.path);
        QVERIFY2(back.ok(), back.ok() ? "" : back.error->toString().c_str());
        QCOMPARE(back.profile.name, venue.name);
        QVERIFY(back.profile.colors == venue.colors);
        QVERIFY(back.warnings.empty());

        const auto list = listColourProfiles(folder);
        QCOMPARE(int(list.size()), 2);
        QCOMPARE(list[0].name, std::string("home lab"));
        QCOMPARE(list[1].name, std::string("Venue field A"));
    }

    void invalidProfileIsNotWritten()
    {
        QTemporaryDir dir;
        ColourProfile p = venueProfile();
        p.colors.classes[2].role = ColourRole::Other;  // no field class left
        const ColourProfileSave s = saveColourProfile(dir.path().toStdString(), p);
        QVERIFY(s.error);
        QCOMPARE(s.error->key, std::string("colors.classes"));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }

    void badFilesAreRefusedWithTheirName_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("key");
        QTest::newRow("a config, not a profile") << "%YAML:1.0\n---\nschema: 1\n" << "colour_profile";
        QTest::newRow("duplicate class")
            << "%YAML:1.0\n---\ncolour_profile: 1\nname: \"x\"\ncolors:\n   classes:\n"
               "      - { name: green, role: field, boxes: [ { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] } ] }\n"
               "      - { name: green, role: line, boxes: [ { h: [ 0, 179 ], s: [ 0, 50 ], v: [ 170, 255 ] } ] }\n"
            << "colors.classes[1].name";
        QTest::newRow("ratio out of range") << "%YAML:1.0\n---\ncolour_profile: 1\nname: \"x\"\ncolors:\n   black_v_ratio: 2.0\n"
                                            << "colors.black_v_ratio";
        QTest::newRow("cut in the middle") << "%YAML:1.0\n---\ncolour_profile: 1\nname: \"x\"\ncolors:\n   classes:\n      - { name: gr"
                                           << "";
    }
    void badFilesAreRefusedWithTheirName()
    {
        QFETCH(QString, text);
        QFETCH(QString, key);
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.yml");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text.toUtf8());
        f.close();
        const ColourProfileLoad load = loadColourProfile(path.toStdString());
        QVERIFY(!load.ok());
        QCOMPARE(QString::fromStdString(load.error->file), path);
        if (!key.isEmpty()) QCOMPARE(QString::fromStdString(load.error->key), key);
        const auto list = listColourProfiles(dir.path().toStdString());
        QCOMPARE(int(list.size()), 1);
        QVERIFY(list[0].error && list[0].name.empty());
    }

    void diffSideBySide()
    {
        const ColourProfile venue = venueProfile();
        ColorLutOptions home;
        home.classes.push_back({"red", ColourRole::Ball, {0, 0, 200}, true, {HsvRange{true, 172, 4, 120, 255, 60, 255}}});
        const auto rows = diffColourCalibrations(home, venue.colors);
        auto row = [&rows](const std::string& what) {
            for (const ColourDiffRow& r : rows)
                if (r.what == what) return r;
            return ColourDiffRow{};
        };
        QVERIFY(row("lut_bits").same);
        QVERIFY(!row("black_v_ratio").same);
        QVERIFY(!row("class green").same);
        QVERIFY(QString::fromStdString(row("class green").right).contains("H 86..98"));
        QVERIFY(row("class white").same);
        QCOMPARE(row("class red").right, std::string("-"));
        QVERIFY(!row("class yellow").same);
        const std::string text = formatColourDiff(rows, "home", "venue");
        QVERIFY(text.find("* class green") != std::string::npos);
        QVERIFY(text.find("  class white") != std::string::npos);
    }

    void pixelsThatChangeClass()
    {
        const ConfigLoad demo = loadConfig(OMNITUNE_SOURCE_DIR "/sessions/demo/config.yml");
        QVERIFY(demo.ok());
        const cv::Mat frame = cv::imread(OMNITUNE_SOURCE_DIR "/sessions/demo/frames/000003.png");
        QVERIFY(!frame.empty());
        const Geometry geometry(demo.config.geometry, demo.config.mask);
        const ClassChanges none = classChanges(frame, PixelFormat::Bgr8, geometry, demo.config.colors, demo.config.colors);
        QVERIFY(none.processed > 10000);
        QCOMPARE(none.changed, 0);

        // White's box reaches down into the bright carpet: those carpet pixels change class.
        ColorLutOptions wider = demo.config.colors;
        wider.classes[std::size_t(ColorClass::White) - 1].boxes.front() = HsvRange{true, 0, 179, 0, 255, 120, 255};
        const ClassChanges some = classChanges(frame, PixelFormat::Bgr8, geometry, demo.config.colors, wider);
        QVERIFY(some.changed > 0 && some.changed < some.processed);
        QCOMPARE(cv::countNonZero(some.mask), some.changed);
        QVERIFY(some.share() > 0.0 && some.share() < 1.0);
        // A changed pixel is one the two LUTs classify differently.
        cv::Point p;
        cv::minMaxLoc(some.mask, nullptr, nullptr, nullptr, &p);
        const cv::Vec3b c = frame.at<cv::Vec3b>(p);
        QVERIFY(ColorLut(demo.config.colors).classifyBgr(c[0], c[1], c[2]) != ColorLut(wider).classifyBgr(c[0], c[1], c[2]) ||
                demo.config.colors.blackRelative);
    }
};

QTEST_GUILESS_MAIN(ColourProfileTest)
#include "calib_colour_profile_test.moc"
