// The declared schema: its defaults are the thesis numbers, every key reads and writes, and
// docs/config.md is the document generated from it.
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"

#include <QtTest>

#include <fstream>
#include <set>
#include <sstream>

using namespace omnitune;

class ConfigSchemaTest : public QObject {
    Q_OBJECT
private slots:
    void docsAreUpToDate()
    {
        const std::string path = std::string(OMNITUNE_SOURCE_DIR) + "/docs/config.md";
        std::ifstream in(path);
        QVERIFY2(in, ("cannot read " + path).c_str());
        std::stringstream s;
        s << in.rdbuf();
        QVERIFY2(s.str() == configSchemaMarkdown(),
                 "docs/config.md is out of date: regenerate it with "
                 "`build/app/omnitune-config --doc > docs/config.md`");
    }

    void defaultsAreValid() { QVERIFY(checkConfig(Config{}).empty()); }

    void everyKeyIsDescribedAndUnique()
    {
        std::set<std::string> seen;
        for (const ConfigKey& k : configSchema()) {
            QVERIFY2(seen.insert(k.path).second, k.path.c_str());
            QVERIFY2(!k.meaning.empty(), k.path.c_str());
            QVERIFY2(k.path.find('.') != std::string::npos, k.path.c_str());
            if (k.type == ValueType::Int || k.type == ValueType::Double) QVERIFY2(k.min <= k.max, k.path.c_str());
            QVERIFY2(k.get && k.set, k.path.c_str());
        }
        QVERIFY(seen.size() > 60);
    }

    void everyKeyIsWritten()
    {
        const std::string yml = serializeConfig(Config{});
        for (const ConfigKey& k : configSchema()) {
            const std::string leaf = k.path.substr(k.path.rfind('.') + 1);
            QVERIFY2(yml.find(leaf + ":") != std::string::npos, k.path.c_str());
        }
    }

    void thesisDefaults_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::newRow("Canny low 60") << "edges.canny_low" << "60";
        QTest::newRow("Canny high 180") << "edges.canny_high" << "180";
        QTest::newRow("six radial areas") << "hough.area_bounds" << "[70, 105, 140, 170, 205, 240]";
        QTest::newRow("near robot 70 px") << "hough.near_robot_radius" << "70";
        QTest::newRow("near robot counts twice") << "hough.near_robot_weight" << "2";
        QTest::newRow("multiple maxima") << "hough.multiple_maxima" << "true";
        QTest::newRow("dp 2") << "opencv_hough.dp" << "2";
        QTest::newRow("min dist 12") << "opencv_hough.min_dist" << "12";
        QTest::newRow("HoughCircles Canny 180") << "opencv_hough.canny_high" << "180";
        QTest::newRow("radius from 3") << "opencv_hough.min_radius" << "3";
        QTest::newRow("radius to 25") << "opencv_hough.max_radius" << "25";
        QTest::newRow("non-green 85") << "validation.min_non_green_pct" << "85";
        QTest::newRow("non-black 50") << "validation.min_non_black_pct" << "50";
        QTest::newRow("circularity 70") << "validation.min_circularity_pct" << "70";
        QTest::newRow("radius +-15%") << "validation.radius_tolerance" << "0.15";
        QTest::newRow("30 fps") << "camera.frame_rate" << "30";
    }
    void thesisDefaults()
    {
        QFETCH(QString, key);
        QFETCH(QString, value);
        const ConfigKey* k = findConfigKey(key.toStdString());
        QVERIFY(k);
        QCOMPARE(QString::fromStdString(formatConfigValue(k->get(Config{}))), value);
        QVERIFY(k->fromThesis);
    }

    void setThenGetEveryKey()
    {
        for (const ConfigKey& k : configSchema()) {
            Config c;
            ConfigValue v = k.get(c);
            if (auto* i = std::get_if<int>(&v)) *i = int(k.max);
            else if (auto* d = std::get_if<double>(&v)) *d = k.max;
            else if (auto* b = std::get_if<bool>(&v)) *b = !*b;
            else if (auto* s = std::get_if<std::string>(&v)) *s = k.type == ValueType::Choice ? k.choices.front() : "x.png";
            else std::get<std::vector<double>>(v).push_back(k.max);
            k.set(c, v);
            QCOMPARE(formatConfigValue(k.get(c)), formatConfigValue(v));
        }
    }
};

QTEST_GUILESS_MAIN(ConfigSchemaTest)
#include "core_config_schema_test.moc"
