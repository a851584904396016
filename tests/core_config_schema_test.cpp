// The declared schema: its defaults are the thesis numbers, every key reads and writes, and
// docs/config.md is the document generated from it.
#include "core/ConfigParser.h"
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"

#include <QtTest>

#include <cctype>
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

    // Every key's row has its six cells: a "|" in a meaning ("|dx|+|dy|") is escaped.
    void docsTableRowsHaveSixCells()
    {
        std::istringstream md(configSchemaMarkdown());
        int rows = 0;
        for (std::string line; std::getline(md, line);) {
            if (line.rfind("| `", 0) != 0) continue;
            ++rows;
            int pipes = 0;
            for (std::size_t i = 0; i < line.size(); ++i) pipes += line[i] == '|' && (i == 0 || line[i - 1] != '\\');
            QVERIFY2(pipes == 7, line.c_str());
        }
        QCOMPARE(rows, int(configSchema().size()));
    }

    void defaultsAreValid() { QVERIFY(checkConfig(Config{}).empty()); }

    // The bundled demo session runs with the defaults: --upgrade keeps a file's values, so a
    // default changed later would otherwise stay old there, and the newcomer's first look at
    // the window would show a detector nobody ships.
    void demoConfigIsTheDefaults()
    {
        const std::string path = std::string(OMNITUNE_SOURCE_DIR) + "/sessions/demo/config.yml";
        const ConfigLoad load = loadConfig(path);
        const std::string error = load.error ? load.error->toString() : "";
        QVERIFY2(load.ok(), error.c_str());
        const std::string warning = load.warnings.empty() ? "" : path + ": " + load.warnings.front().toString();
        QVERIFY2(load.warnings.empty(), warning.c_str());
        std::istringstream demo(serializeConfig(load.config));
        std::istringstream defaults(serializeConfig(Config{}));
        std::string a, b;
        while (std::getline(defaults, a)) {
            QVERIFY(std::getline(demo, b));
            const std::string why = path + " differs from the default: '" + b + "' (default '" + a + "'); set it to the default";
            QVERIFY2(a == b, why.c_str());
        }
    }

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

    // A meaning (the panel's tooltip) never repeats a default of its section: the panel shows
    // the key's default from the schema, and a copy in the text goes stale when it changes.
    void meaningsRepeatNoDefault()
    {
        const Config defaults;
        for (const ConfigKey& k : configSchema()) {
            if (k.type != ValueType::Int && k.type != ValueType::Double) continue;
            const std::string value = formatConfigValue(k.get(defaults));
            if (value == "0" || value == "1") continue;  // too common in words ("0: off")
            if (value == formatConfigValue(ConfigValue(k.min)) || value == formatConfigValue(ConfigValue(k.max)))
                continue;  // a scale's end ("hue 0..179") is no tuned default
            const std::string section = k.path.substr(0, k.path.find('.') + 1);
            for (const ConfigKey& other : configSchema()) {
                if (other.path.compare(0, section.size(), section) != 0) continue;  // its own section's texts
                const std::string& m = other.meaning;
                for (std::size_t at = m.find(value); at != std::string::npos; at = m.find(value, at + 1)) {
                    const auto numberChar = [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)) || ch == '.'; };
                    const bool before = at > 0 && numberChar(m[at - 1]);
                    const bool after = at + value.size() < m.size() && numberChar(m[at + value.size()]) &&
                                       !(m[at + value.size()] == '.' && at + value.size() + 1 == m.size());
                    QVERIFY2(before || after, (other.path + " repeats " + k.path + "'s default " + value + ": " + m).c_str());
                }
            }
        }
    }

    // Defaults: the thesis' numbers (marked so in the docs), and the constants we tuned, which
    // are keys too with the values the detector had when they were literals.
    void defaults_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::addColumn<bool>("thesis");
        QTest::newRow("Canny low 60") << "edges.canny_low" << "60" << true;
        QTest::newRow("Canny high 180") << "edges.canny_high" << "180" << true;
        QTest::newRow("six radial areas") << "hough.area_bounds" << "[70, 105, 140, 170, 205, 240]" << true;
        QTest::newRow("near robot 70 px") << "hough.near_robot_radius" << "70" << true;
        QTest::newRow("near robot counts twice") << "hough.near_robot_weight" << "2" << true;
        QTest::newRow("multiple maxima") << "hough.multiple_maxima" << "true" << true;
        QTest::newRow("dp 2") << "opencv_hough.dp" << "2" << true;
        QTest::newRow("min dist 12") << "opencv_hough.min_dist" << "12" << true;
        QTest::newRow("HoughCircles Canny 180") << "opencv_hough.canny_high" << "180" << true;
        QTest::newRow("radius from 3") << "opencv_hough.min_radius" << "3" << true;
        QTest::newRow("radius to 25") << "opencv_hough.max_radius" << "25" << true;
        QTest::newRow("non-green 85") << "validation.min_non_green_pct" << "85" << true;
        QTest::newRow("non-black 30") << "validation.min_non_black_pct" << "30" << false;
        QTest::newRow("circularity 70") << "validation.min_circularity_pct" << "70" << true;
        QTest::newRow("radius +-15%") << "validation.radius_tolerance" << "0.15" << true;
        QTest::newRow("30 fps") << "camera.frame_rate" << "30" << true;
        QTest::newRow("run-on reach 1.3 radii") << "validation.run_on_reach" << "1.3" << false;
        QTest::newRow("usable rays 25 %") << "validation.min_usable_ray_share" << "0.25" << false;
        QTest::newRow("look 1.5 px beyond") << "validation.beyond_edge_px" << "1.5" << false;
    }
    void defaults()
    {
        QFETCH(QString, key);
        QFETCH(QString, value);
        QFETCH(bool, thesis);
        const ConfigKey* k = findConfigKey(key.toStdString());
        QVERIFY(k);
        QCOMPARE(QString::fromStdString(formatConfigValue(k->get(Config{}))), value);
        QCOMPARE(k->fromThesis, thesis);
        QVERIFY(k->min < k->max);
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
