// The colour-class model (core/ColourClasses.h) and its config form (colors.classes): the
// default classes classify every LUT colour as the thesis' fixed classes did, roles (not names)
// drive the binary image, the list reads and writes back, bad lists are refused with the key,
// and a config in the old per-class keys loads unchanged in meaning.
#include "core/ColorLut.h"
#include "core/ColourClassesYaml.h"
#include "core/ConfigParser.h"
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"
#include "core/Edges.h"
#include "core/Geometry.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <algorithm>

using namespace omnitune;

namespace {

// The thesis' classes as the detector had them before colors.classes: fixed HSV ranges tested in
// the order black, white, green, orange, cyan, magenta. Written out here, so that the test fails
// when the defaults' meaning drifts.
std::string oldClassifyHsv(int h, int s, int v)
{
    struct Old {
        const char* name;
        int h0, h1, s0, s1, v0, v1;
    };
    static const Old old[] = {{"black", 0, 179, 0, 255, 0, 60},     {"white", 0, 179, 0, 50, 170, 255},
                              {"green", 35, 85, 60, 255, 40, 255},  {"orange", 5, 22, 120, 255, 80, 255},
                              {"cyan", 86, 105, 120, 255, 80, 255}, {"magenta", 140, 170, 100, 255, 80, 255}};
    for (const Old& o : old)
        if (h >= o.h0 && h <= o.h1 && s >= o.s0 && s <= o.s1 && v >= o.v0 && v <= o.v1) return o.name;
    return "unknown";
}

// Every bin centre of a `bits` table, as a 1 x N BGR image.
cv::Mat binCentres(int bits)
{
    const int levels = 1 << bits;
    const int shift = 8 - bits;
    const int half = (1 << shift) / 2;
    cv::Mat grid(1, levels * levels * levels, CV_8UC3);
    for (int i = 0; i < grid.cols; ++i)
        grid.at<cv::Vec3b>(0, i) = cv::Vec3b(uchar((((i >> (2 * bits)) & (levels - 1)) << shift) + half),
                                             uchar((((i >> bits) & (levels - 1)) << shift) + half),
                                             uchar(((i & (levels - 1)) << shift) + half));
    return grid;
}

// A geometry that processes every pixel of a small image.
Geometry wholeImage(int width, int height)
{
    GeometryOptions g;
    g.imageWidth = width;
    g.imageHeight = height;
    g.centerX = width / 2.0;
    g.centerY = height / 2.0;
    g.innerRadius = 0;
    g.outerRadius = width + height;
    return Geometry(g, cv::Mat());
}

std::string configText(const std::string& classes)
{
    return "%YAML:1.0\n---\nschema: 1\ncolors:\n   classes:\n" + classes;
}

const char* kGreen = "      - name: green\n        role: field\n        boxes:\n           - { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] }\n";

}  // namespace

class ColourClassesTest : public QObject {
    Q_OBJECT
private slots:
    // Over all 2^18 colours of the default 6-bit table: the default classes give every colour the
    // class the old fixed ranges gave it (thesis' black, no relative black, so the boxes decide).
    void defaultsClassifyAsTheOldFixedClasses()
    {
        ColorLutOptions o;
        o.blackRelative = false;
        const ColorLut lut(o);
        const cv::Mat grid = binCentres(o.bits);
        cv::Mat hsv;
        cv::cvtColor(grid, hsv, cv::COLOR_BGR2HSV);
        const std::vector<std::uint8_t> table = lut.bgrTable();
        QCOMPARE(int(table.size()), grid.cols);
        int mismatches = 0;
        for (int i = 0; i < grid.cols; ++i) {
            const cv::Vec3b h = hsv.at<cv::Vec3b>(0, i);
            const cv::Vec3b p = grid.at<cv::Vec3b>(0, i);
            const std::string want = oldClassifyHsv(h[0], h[1], h[2]);
            mismatches += colourClassName(o.classes, ColorClass(table[std::size_t(i)])) != want;
            mismatches += colourClassName(o.classes, lut.classifyBgr(p[0], p[1], p[2])) != want;
        }
        QCOMPARE(mismatches, 0);
    }

    // The default ids are ColorClass's named values, and yellow is there but off.
    void defaultIdsAndYellow()
    {
        const ColourClasses d = defaultColourClasses();
        QCOMPARE(colourClassName(d, ColorClass::Green), std::string("green"));
        QCOMPARE(colourClassName(d, ColorClass::Black), std::string("black"));
        QCOMPARE(colourClassName(d, ColorClass::Yellow), std::string("yellow"));
        QVERIFY(!d[std::size_t(ColorClass::Yellow) - 1].enabled);
        QVERIFY(checkColourClasses(d).empty());
        const ColorLut lut{ColorLutOptions{}};
        QCOMPARE(lut.classifyBgr(20, 200, 220), ColorClass::Unknown);  // yellow, hue ~27
        ColorLutOptions on;
        on.classes[std::size_t(ColorClass::Yellow) - 1].enabled = true;
        QCOMPARE(ColorLut(on).classifyBgr(20, 200, 220), ColorClass::Yellow);
    }

    // The binary image and the LUT's carpet follow roles: a second field class (cyan-green) is
    // carpet, a class named "green" whose role is other is not.
    void rolesNotNamesMakeTheBinary()
    {
        ColorLutOptions o;
        o.blackRelative = false;
        ColourClassDef cyanGreen{"cyan_green", ColourRole::Field, {160, 160, 0}, true, {HsvRange{true, 86, 100, 60, 255, 40, 255}}};
        o.classes.insert(o.classes.begin() + 3, cyanGreen);  // before cyan: it wins the overlap
        o.classes[2].role = ColourRole::Other;                // "green" no longer carpet
        const ColorLut lut(o);
        const ColourRoles roles(o.classes);
        const ColorClass cg = lut.classifyBgr(200, 190, 40);  // hue ~92
        QCOMPARE(colourClassName(o.classes, cg), std::string("cyan_green"));
        QVERIFY(roles.field(std::uint8_t(cg)));
        QVERIFY(lut.isField(cg));
        const ColorClass green = lut.classifyBgr(40, 140, 40);
        QCOMPARE(colourClassName(o.classes, green), std::string("green"));
        QVERIFY(!roles.field(std::uint8_t(green)));

        const Geometry geo = wholeImage(4, 1);
        cv::Mat classes = (cv::Mat_<std::uint8_t>(1, 4) << std::uint8_t(cg), std::uint8_t(green), 2, 0);
        cv::Mat binary;
        makeBinary(classes, geo, binary, 128, roles);
        QCOMPARE(int(binary.at<std::uint8_t>(0, 0)), 255);  // cyan-green: field
        QCOMPARE(int(binary.at<std::uint8_t>(0, 1)), 0);    // "green" of role other
        QCOMPARE(int(binary.at<std::uint8_t>(0, 2)), 128);  // white: line
        QCOMPARE(int(binary.at<std::uint8_t>(0, 3)), 0);    // unknown
    }

    // A wrapped red hue range classifies reds on both sides of 0, as a second box of a class.
    void wrappedRedBox()
    {
        ColorLutOptions o;
        o.classes.push_back({"red", ColourRole::Ball, {0, 0, 255}, true,
                             {HsvRange{true, 175, 179, 150, 255, 80, 255}, HsvRange{true, 170, 4, 150, 255, 80, 255}}});
        const ColorLut lut(o);
        const ColorClass red = colourClassId(int(o.classes.size()) - 1);
        QCOMPARE(lut.classifyBgr(20, 20, 220), red);          // hue 0
        QCOMPARE(lut.classifyBgr(50, 20, 220), red);          // hue ~176
        QCOMPARE(lut.classifyBgr(20, 35, 220), red);          // hue ~2
        QCOMPARE(lut.classifyBgr(20, 110, 240), ColorClass::Orange);
    }

    // Relative black with the black class moved down the list and two field classes: dark pixels
    // are still the black class, the carpet's V comes from both field classes.
    void relativeBlackByRole()
    {
        ColorLutOptions o;
        std::rotate(o.classes.begin(), o.classes.begin() + 1, o.classes.end());  // black last
        const ColorClass black = colourClassId(int(o.classes.size()) - 1);
        const ColorLut lut(o);
        const Geometry geo = wholeImage(40, 40);
        cv::Mat frame(40, 40, CV_8UC3, cv::Scalar(30, 90, 30));             // dim carpet, V 90
        cv::rectangle(frame, cv::Rect(0, 0, 10, 10), cv::Scalar(20, 25, 30), cv::FILLED);  // robot, V 30
        cv::Mat classes(40, 40, CV_8UC1, cv::Scalar(0));
        SegmentStats stats;
        lut.segment(frame, PixelFormat::Bgr8, geo.spans(), classes, &stats);
        QVERIFY(std::abs(stats.carpetV - 90) <= 8);
        QCOMPARE(classes.at<std::uint8_t>(5, 5), std::uint8_t(black));
        QCOMPARE(classes.at<std::uint8_t>(30, 30), std::uint8_t(ColorClass::White));  // green moved to id 2
        QCOMPARE(colourClassName(o.classes, ColorClass(classes.at<std::uint8_t>(30, 30))), std::string("green"));
    }

    void writeAndReadBack()
    {
        Config c;
        c.colors.classes.push_back({"red", ColourRole::Ball, {10, 20, 250}, true,
                                    {HsvRange{true, 170, 8, 150, 255, 80, 255}, HsvRange{false, 0, 3, 100, 255, 60, 255}}});
        c.colors.classes[2].boxes.push_back(HsvRange{true, 80, 95, 40, 255, 30, 255});
        c.colors.classes[4].enabled = false;
        c.validation.ballHint = "red";
        const std::string text = serializeConfig(c);
        const ConfigLoad back = parseConfig(text, "c.yml");
        QVERIFY2(back.ok(), back.ok() ? "" : back.error->toString().c_str());
        QVERIFY(back.config.colors.classes == c.colors.classes);
        QCOMPARE(back.config.validation.ballHint, std::string("red"));
        for (const auto& w : back.warnings) QVERIFY2(false, w.toString().c_str());
        QVERIFY(text.find("role: field") != std::string::npos);
    }

    void badListsRefusedWithTheKey_data()
    {
        QTest::addColumn<QString>("classes");
        QTest::addColumn<QString>("key");
        QTest::newRow("class with no box") << QString(kGreen) + "      - name: ball\n        role: ball\n        boxes: []\n"
                                           << "colors.classes[1].boxes";
        QTest::newRow("empty box (s min above max)")
            << QString(kGreen) + "      - name: ball\n        role: ball\n        boxes:\n           - { h: [ 5, 20 ], s: [ 200, 100 ], v: [ 0, 255 ] }\n"
            << "colors.classes[1].boxes[0].s";
        QTest::newRow("empty box (v min above max)")
            << QString(kGreen) + "      - name: ball\n        role: ball\n        boxes:\n           - { h: [ 5, 20 ], s: [ 0, 255 ], v: [ 90, 80 ] }\n"
            << "colors.classes[1].boxes[0].v";
        QTest::newRow("duplicate name") << QString(kGreen) + kGreen << "colors.classes[1].name";
        QTest::newRow("no field class")
            << "      - name: green\n        role: other\n        boxes:\n           - { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] }\n"
            << "colors.classes";
        QTest::newRow("unknown role") << "      - name: green\n        role: carpet\n        boxes:\n           - { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] }\n"
                                      << "colors.classes[0].role";
        QTest::newRow("hue out of scale") << "      - name: green\n        role: field\n        boxes:\n           - { h: [ 35, 185 ], s: [ 60, 255 ], v: [ 40, 255 ] }\n"
                                          << "colors.classes[0].boxes[0].h";
        QTest::newRow("box without v") << "      - name: green\n        role: field\n        boxes:\n           - { h: [ 35, 85 ], s: [ 60, 255 ] }\n"
                                       << "colors.classes[0].boxes[0].v";
        QTest::newRow("upper-case name") << "      - name: Green\n        role: field\n        boxes:\n           - { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] }\n"
                                         << "colors.classes[0].name";
        QString sixteen;
        for (int i = 0; i < 16; ++i)
            sixteen += QStringLiteral("      - name: c%1\n        role: field\n        boxes:\n           - { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] }\n").arg(i);
        QTest::newRow("16 classes") << sixteen << "colors.classes";
    }
    void badListsRefusedWithTheKey()
    {
        QFETCH(QString, classes);
        QFETCH(QString, key);
        const ConfigLoad load = parseConfig(configText(classes.toStdString()), "bad.yml");
        QVERIFY(!load.ok());
        QCOMPARE(QString::fromStdString(load.error->key), key);
        QCOMPARE(load.error->file, std::string("bad.yml"));
    }

    // A hue range whose min is above its max wraps: allowed.
    void wrappedHueAllowed()
    {
        const ConfigLoad load = parseConfig(
            configText(std::string(kGreen) + "      - name: red\n        role: ball\n        boxes:\n           - { h: [ 170, 10 ], s: [ 100, 255 ], v: [ 60, 255 ] }\n"),
            "ok.yml");
        QVERIFY2(load.ok(), load.ok() ? "" : load.error->toString().c_str());
        QCOMPARE(int(load.config.colors.classes.size()), 2);
    }

    void ballHintMustNameAClass()
    {
        Config c;
        c.validation.ballHint = "purple";
        auto problems = checkConfig(c);
        QVERIFY(!problems.empty());
        QCOMPARE(problems.front().key, std::string("validation.ball_hint_class"));
        c.validation.ballHint = "green";  // a field class: the ball is never carpet
        QVERIFY(!checkConfig(c).empty());
        c.validation.ballHint = "yellow";
        QVERIFY(checkConfig(c).empty());
    }

    // The old per-class keys load as before (with a warning naming --upgrade), and the file
    // written from them, read again, gives the identical LUT over every colour.
    void oldFormReadsUnchangedInMeaning()
    {
        const std::string old =
            "%YAML:1.0\n---\nschema: 1\ncolors:\n   lut_bits: 6\n   black_relative: 0\n"
            "   black:\n      enabled: 1\n      h_min: 0\n      h_max: 179\n      s_min: 0\n      s_max: 255\n      v_min: 0\n      v_max: 50\n"
            "   green:\n      enabled: 1\n      h_min: 40\n      h_max: 95\n      s_min: 70\n      s_max: 255\n      v_min: 30\n      v_max: 255\n"
            "   orange:\n      enabled: 0\n      h_min: 5\n      h_max: 22\n      s_min: 120\n      s_max: 255\n      v_min: 80\n      v_max: 255\n"
            "   magenta:\n      h_min: 170\n      h_max: 8\n";
        const ConfigLoad load = parseConfig(old, "old.yml");
        QVERIFY2(load.ok(), load.ok() ? "" : load.error->toString().c_str());
        bool warned = false;
        for (const auto& w : load.warnings) {
            warned = warned || (w.kind == ConfigIssueKind::OldForm && w.message.find("--upgrade") != std::string::npos);
            QVERIFY2(w.kind != ConfigIssueKind::UnknownKey, w.toString().c_str());
        }
        QVERIFY(warned);
        const ColourClasses& cl = load.config.colors.classes;
        QCOMPARE(cl[2].boxes.front(), (HsvRange{true, 40, 95, 70, 255, 30, 255}));
        QCOMPARE(cl[0].boxes.front().vMax, 50);
        QVERIFY(!cl[3].enabled);
        QCOMPARE(cl[5].boxes.front().hMin, 170);  // given
        QCOMPARE(cl[5].boxes.front().sMin, 100);  // missing: the default
        QCOMPARE(cl[1], defaultColourClasses()[1]);  // a missing section: the default class

        const ConfigLoad upgraded = parseConfig(serializeConfig(load.config), "upgraded.yml");
        QVERIFY(upgraded.ok());
        for (const auto& w : upgraded.warnings) QVERIFY2(w.kind != ConfigIssueKind::OldForm, w.toString().c_str());
        for (bool relative : {false, true}) {
            ColorLutOptions a = load.config.colors;
            ColorLutOptions b = upgraded.config.colors;
            a.blackRelative = b.blackRelative = relative;
            QVERIFY(ColorLut(a).bgrTable() == ColorLut(b).bgrTable());
        }
        // Meaning: the old fixed ranges, tested in the old order.
        const ColorLut lut(upgraded.config.colors);
        QCOMPARE(lut.classifyBgr(40, 140, 40), ColorClass::Green);
        QCOMPARE(lut.classifyBgr(20, 110, 240), ColorClass::Unknown);  // orange was off
        QCOMPARE(lut.classifyBgr(20, 20, 220), ColorClass::Magenta);   // hue 0 in 170..8
    }

    // An unknown key inside a class is reported, not silently dropped.
    void unknownKeyInAClassWarns()
    {
        const ConfigLoad load = parseConfig(
            configText("      - name: green\n        role: field\n        colour: [ 1, 2, 3 ]\n        boxes:\n           - { h: [ 35, 85 ], s: [ 60, 255 ], v: [ 40, 255 ] }\n"),
            "typo.yml");
        QVERIFY(load.ok());
        bool found = false;
        for (const auto& w : load.warnings) found = found || w.key == "colors.classes[0].colour";
        QVERIFY(found);
    }
};

QTEST_GUILESS_MAIN(ColourClassesTest)
#include "core_colour_classes_test.moc"
