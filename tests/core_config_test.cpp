// config.yml: round trip, atomic save with backup, and load errors that name file and key.
#include "core/ConfigParser.h"
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <fstream>
#include <sstream>

using namespace omnitune;
Q_DECLARE_METATYPE(omnitune::ConfigIssueKind)

namespace {

std::string readFile(const QString& path)
{
    std::ifstream in(path.toStdString(), std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeFile(const QString& path, const std::string& text)
{
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << text;
}

// A config that differs from the defaults in every section.
Config changedConfig()
{
    Config c;
    c.camera.model = "Flea2 robot 3";
    c.camera.exposure = 412;
    c.camera.gain = 17;
    c.colors.bits = 7;
    c.colors.ranges[std::size_t(ColorClass::Orange)] = HsvRange{true, 172, 12, 100, 250, 70, 240};
    c.colors.ranges[std::size_t(ColorClass::Cyan)].enabled = false;
    c.geometry = GeometryOptions{505, 480, 251.5, 238.25, 44, 236, ""};
    c.sensors.count = 120;
    c.distanceMap.pixelRadii = {0, 60, 120, 236};
    c.distanceMap.groundDistances = {0, 0.5, 1.7, 6.0};
    c.ball.c1 = -0.3;
    c.edges = EdgeOptions{55, 170};
    c.hough.multipleMaxima = false;
    c.hough.areaBounds = {60, 120, 236};
    c.opencvHough.accThreshold = 31.5;
    c.validation.minCircularityPct = 66.5;
    c.algorithm = Algorithm::Specific;
    return c;
}

bool sameConfig(const Config& a, const Config& b, QString* firstDifference)
{
    for (const ConfigKey& k : configSchema())
        if (formatConfigValue(k.get(a)) != formatConfigValue(k.get(b))) {
            *firstDifference = QString::fromStdString(k.path + ": " + formatConfigValue(k.get(a)) + " vs " +
                                                      formatConfigValue(k.get(b)));
            return false;
        }
    return true;
}

std::string withKey(const std::string& section, const std::string& body)
{
    return "schema: 1\n" + section + ":\n" + body;
}

}  // namespace

class ConfigTest : public QObject {
    Q_OBJECT
private slots:
    void roundTrip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        const Config c = changedConfig();
        QVERIFY(!saveConfig(c, path.toStdString()));
        const ConfigLoad load = loadConfig(path.toStdString());
        QVERIFY2(load.ok(), load.error ? load.error->toString().c_str() : "");
        QVERIFY(load.warnings.empty());
        QString diff;
        QVERIFY2(sameConfig(c, load.config, &diff), qPrintable(diff));
        QString diffDefault;
        QVERIFY(!sameConfig(Config{}, load.config, &diffDefault));
    }

    void saveIsAtomicAndKeepsABackup()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        Config a;
        a.edges.cannyLow = 41;
        QVERIFY(!saveConfig(a, path.toStdString()));
        QVERIFY(!QFile::exists(path + ".bak"));  // nothing to back up the first time
        Config b;
        b.edges.cannyLow = 42;
        QVERIFY(!saveConfig(b, path.toStdString()));
        QCOMPARE(loadConfig(path.toStdString()).config.edges.cannyLow, 42);
        QCOMPARE(loadConfig((path + ".bak").toStdString()).config.edges.cannyLow, 41);
        QVERIFY(!QFile::exists(path + ".tmp"));
    }

    void invalidConfigIsNotSaved()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        QVERIFY(!saveConfig(Config{}, path.toStdString()));
        const std::string before = readFile(path);
        Config bad;
        bad.edges.cannyLow = 500;
        bad.edges.cannyHigh = 100;
        const auto err = saveConfig(bad, path.toStdString());
        QVERIFY(err);
        QCOMPARE(QString::fromStdString(err->key), QString("edges.canny_low"));
        QCOMPARE(readFile(path), before);
    }

    void saveIntoMissingFolderFails()
    {
        const auto err = saveConfig(Config{}, "/nonexistent-folder/config.yml");
        QVERIFY(err);
        QCOMPARE(err->kind, ConfigIssueKind::WriteError);
        QVERIFY(QString::fromStdString(err->message).contains("/nonexistent-folder/config.yml"));
    }

    void loadErrors_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<ConfigIssueKind>("kind");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("says");
        QTest::newRow("empty file") << QByteArray("  \n") << ConfigIssueKind::ParseError << "" << "empty";
        QTest::newRow("not YAML") << QByteArray("schema: 1\nedges: {canny_low: [1, 2\n  ]]] }:\n")
                                  << ConfigIssueKind::ParseError << "" << "not a valid YAML";
        QTest::newRow("binary garbage") << QByteArray("\x89PNG\r\n\x1a\n\x01\x02\x03", 11) << ConfigIssueKind::ParseError << "" << "";
        QTest::newRow("no schema") << QByteArray("edges:\n  canny_low: 3\n") << ConfigIssueKind::NotAConfig << "schema" << "not an OmniTune config";
        QTest::newRow("future schema") << QByteArray("schema: 7\n") << ConfigIssueKind::UnknownSchema << "schema" << "schema 7";
        QTest::newRow("text for a number") << QByteArray(withKey("edges", "  canny_low: abc\n").c_str())
                                           << ConfigIssueKind::WrongType << "edges.canny_low" << "expected integer";
        QTest::newRow("fraction for an integer") << QByteArray(withKey("edges", "  canny_low: 60.5\n").c_str())
                                                 << ConfigIssueKind::WrongType << "edges.canny_low" << "found a number";
        QTest::newRow("out of range") << QByteArray(withKey("edges", "  canny_low: 5000\n").c_str())
                                      << ConfigIssueKind::OutOfRange << "edges.canny_low" << "outside 0..1020";
        QTest::newRow("percentage above 100") << QByteArray(withKey("validation", "  min_non_green_pct: 185\n").c_str())
                                              << ConfigIssueKind::OutOfRange << "validation.min_non_green_pct" << "185";
        QTest::newRow("low above high") << QByteArray(withKey("edges", "  canny_low: 200\n  canny_high: 100\n").c_str())
                                        << ConfigIssueKind::Inconsistent << "edges.canny_low" << "above canny_high";
        QTest::newRow("areas not increasing") << QByteArray(withKey("hough", "  area_bounds: [70, 105, 100]\n").c_str())
                                              << ConfigIssueKind::Inconsistent << "hough.area_bounds" << "increasing";
        QTest::newRow("text in a list") << QByteArray(withKey("hough", "  area_bounds: [70, x, 100]\n").c_str())
                                        << ConfigIssueKind::WrongType << "hough.area_bounds" << "list of numbers";
        QTest::newRow("unknown algorithm") << QByteArray(withKey("algorithm", "  method: fastest\n").c_str())
                                           << ConfigIssueKind::WrongType << "algorithm.method" << "fastest";
        QTest::newRow("boolean as 2") << QByteArray(withKey("hough", "  multiple_maxima: 2\n").c_str())
                                      << ConfigIssueKind::WrongType << "hough.multiple_maxima" << "0/1";
        QTest::newRow("distance map sizes differ")
            << QByteArray(withKey("distance_map", "  pixel_radii: [0, 10, 20]\n  ground_distances: [0, 1]\n").c_str())
            << ConfigIssueKind::Inconsistent << "distance_map.ground_distances" << "same number";
        const std::string saved = serializeConfig(Config{});
        QTest::newRow("truncated saved file") << QByteArray(saved.substr(0, saved.size() * 2 / 3).c_str())
                                              << ConfigIssueKind::ParseError << "" << "";
    }
    void loadErrors()
    {
        QFETCH(QByteArray, text);
        QFETCH(ConfigIssueKind, kind);
        QFETCH(QString, key);
        QFETCH(QString, says);
        QTemporaryDir dir;
        const QString path = dir.filePath("robot3.yml");
        writeFile(path, text.toStdString());
        const ConfigLoad load = loadConfig(path.toStdString());
        QVERIFY(!load.ok());
        const QString message = QString::fromStdString(load.error->toString());
        QVERIFY2(load.error->kind == kind, qPrintable(message));
        if (!key.isEmpty()) QCOMPARE(QString::fromStdString(load.error->key), key);
        QVERIFY2(message.startsWith(path), qPrintable(message));  // names the file
        if (!key.isEmpty()) QVERIFY2(message.contains(key), qPrintable(message));
        QVERIFY2(message.contains(says), qPrintable(message));
    }

    void parseErrorsGiveALine()
    {
        const ConfigLoad load = parseConfig("schema: 1\nedges:\n  canny_low: 60\n   canny_high: [\n", "c.yml");
        QVERIFY(!load.ok());
        QCOMPARE(load.error->kind, ConfigIssueKind::ParseError);
        QVERIFY2(load.error->line >= 3 && load.error->line <= 5, qPrintable(QString::number(load.error->line)));
    }

    void missingKeyWarnsAndUsesTheDefault()
    {
        const ConfigLoad load = parseConfig(withKey("edges", "  canny_low: 50\n"), "c.yml");
        QVERIFY(load.ok());
        QCOMPARE(load.config.edges.cannyLow, 50);
        QCOMPARE(load.config.edges.cannyHigh, 180);
        const auto it = std::find_if(load.warnings.begin(), load.warnings.end(),
                                     [](const ConfigIssue& w) { return w.key == "edges.canny_high"; });
        QVERIFY(it != load.warnings.end());
        QCOMPARE(it->kind, ConfigIssueKind::MissingKey);
        QVERIFY(QString::fromStdString(it->message).contains("180"));
    }

    void unknownKeyWarns()
    {
        const ConfigLoad load = parseConfig(withKey("edges", "  canny_lwo: 50\n"), "c.yml");
        QVERIFY(load.ok());
        const auto it = std::find_if(load.warnings.begin(), load.warnings.end(),
                                     [](const ConfigIssue& w) { return w.kind == ConfigIssueKind::UnknownKey; });
        QVERIFY(it != load.warnings.end());
        QCOMPARE(QString::fromStdString(it->key), QString("edges.canny_lwo"));
    }

    void acceptsTrueFalseForBooleans()
    {
        const ConfigLoad load = parseConfig(withKey("hough", "  multiple_maxima: false\n"), "c.yml");
        QVERIFY(load.ok());
        QCOMPARE(load.config.hough.multipleMaxima, false);
    }

    void missingFileIsNamed()
    {
        const ConfigLoad load = loadConfig("/no/such/dir/config.yml");
        QVERIFY(!load.ok());
        QCOMPARE(load.error->kind, ConfigIssueKind::FileUnreadable);
        QVERIFY(QString::fromStdString(load.error->toString()).contains("/no/such/dir/config.yml"));
    }

    void maskIsSavedAndLoadedBesideTheConfig()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        Config c;
        c.geometry.maskFile = "mask.png";
        c.mask = cv::Mat(480, 640, CV_8UC1, cv::Scalar(255));
        cv::rectangle(c.mask, cv::Rect(300, 0, 40, 200), cv::Scalar(0), cv::FILLED);
        QVERIFY(!saveConfig(c, path.toStdString()));
        QVERIFY(QFile::exists(dir.filePath("mask.png")));
        const ConfigLoad load = loadConfig(path.toStdString());
        QVERIFY(load.ok());
        QCOMPARE(cv::countNonZero(load.config.mask != c.mask), 0);
    }

    void aFailedSaveLeavesTheMaskAndTheConfigAsTheyWere()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        Config c;
        c.geometry.maskFile = "mask.png";
        c.mask = cv::Mat(480, 640, CV_8UC1, cv::Scalar(255));
        QVERIFY(!saveConfig(c, path.toStdString()));
        QFile maskFile(dir.filePath("mask.png"));
        QVERIFY(maskFile.open(QIODevice::ReadOnly));
        const QByteArray maskBefore = maskFile.readAll();
        maskFile.close();
        QVERIFY(QDir(dir.path()).mkdir("config.yml.tmp"));  // the config's temp file cannot be created

        cv::rectangle(c.mask, cv::Rect(0, 0, 100, 100), cv::Scalar(0), cv::FILLED);
        const auto err = saveConfig(c, path.toStdString());
        QVERIFY(err);
        QVERIFY2(QString::fromStdString(err->toString()).contains("config.yml.tmp"), err->toString().c_str());
        QVERIFY(maskFile.open(QIODevice::ReadOnly));
        QCOMPARE(maskFile.readAll(), maskBefore);  // the new mask never replaced the old one
        QVERIFY(!QFile::exists(dir.filePath("mask.png.tmp")));
    }

    void maskProblemsAreNamed_data()
    {
        QTest::addColumn<bool>("writeMask");
        QTest::addColumn<QString>("says");
        QTest::newRow("mask file missing") << false << "cannot read the mask image";
        QTest::newRow("mask of the wrong size") << true << "320x240";
    }
    void maskProblemsAreNamed()
    {
        QFETCH(bool, writeMask);
        QFETCH(QString, says);
        QTemporaryDir dir;
        const QString path = dir.filePath("config.yml");
        Config c;
        c.geometry.maskFile = "rods.png";
        QVERIFY(!saveConfig(c, path.toStdString()));
        if (writeMask) cv::imwrite(dir.filePath("rods.png").toStdString(), cv::Mat(240, 320, CV_8UC1, cv::Scalar(255)));
        const ConfigLoad load = loadConfig(path.toStdString());
        QVERIFY(!load.ok());
        QCOMPARE(load.error->kind, ConfigIssueKind::MaskError);
        const QString message = QString::fromStdString(load.error->toString());
        QVERIFY2(message.contains(says), qPrintable(message));
        QVERIFY2(message.contains("geometry.mask_file"), qPrintable(message));
    }
};

QTEST_GUILESS_MAIN(ConfigTest)
#include "core_config_test.moc"
