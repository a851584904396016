// diffConfigs: what the window's crash recovery lists and restores. Every schema key that
// differs appears once, in schema order, with both values; equal configs give nothing.
#include "calib/config/ConfigDiff.h"

#include <QtTest>

using namespace omnitune;

class ConfigDiffTest : public QObject {
    Q_OBJECT
private slots:
    void equalConfigsGiveNothing()
    {
        Config a;
        Config b;
        QVERIFY(diffConfigs(a, b).empty());
        b.mask = cv::Mat(480, 640, CV_8UC1, cv::Scalar(255));  // not a schema key
        QVERIFY(diffConfigs(a, b).empty());
    }

    // The class list is no schema key; an edit of it (the class editor) is one change carrying the
    // recovered classes, so crash recovery can restore it.
    void colourClassesAreOneChange()
    {
        const Config saved;
        Config recovered;
        recovered.colors.classes[2].boxes.push_back(HsvRange{true, 86, 98, 50, 255, 30, 255});
        auto changes = diffConfigs(saved, recovered);
        QCOMPARE(int(changes.size()), 1);
        QCOMPARE(changes[0].key, std::string("colors.classes"));
        QVERIFY(changes[0].classes == recovered.colors.classes);
        QVERIFY(QString::fromStdString(changes[0].toString()).contains("boxes or roles edited"));
        recovered.colors.classes.pop_back();
        changes = diffConfigs(saved, recovered);
        QCOMPARE(int(changes.size()), 1);
        QVERIFY(QString::fromStdString(changes[0].toString()).contains("6 classes"));
    }

    void everyChangedKeyOnceInSchemaOrder()
    {
        const Config saved;
        Config recovered;
        recovered.edges.cannyHigh = saved.edges.cannyHigh + 20;
        recovered.edges.cannyLow = saved.edges.cannyLow + 15;
        recovered.algorithm = Algorithm::OpenCv;
        recovered.hough.areaBounds = {70, 110};
        recovered.validation.firstEdgeOnly = !saved.validation.firstEdgeOnly;

        const auto changes = diffConfigs(saved, recovered);
        QStringList keys;
        for (const ConfigChange& c : changes) keys << QString::fromStdString(c.key);
        QStringList expected;  // the schema's order, whatever order the fields were changed in
        for (const ConfigKey& k : configSchema())
            if (k.path == "edges.canny_low" || k.path == "edges.canny_high" || k.path == "algorithm.method" ||
                k.path == "hough.area_bounds" || k.path == "validation.first_edge_only")
                expected << QString::fromStdString(k.path);
        QCOMPARE(keys, expected);

        for (const ConfigChange& c : changes) {
            const ConfigKey* k = findConfigKey(c.key);
            QVERIFY(k);
            QVERIFY(c.from == k->get(saved));
            QVERIFY(c.to == k->get(recovered));
        }
    }

    void linesSaySavedThenRecovered_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("line");
        QTest::newRow("integer") << "edges.canny_low" << QString::fromUtf8("edges.canny_low: 60 \u2192 75");
        QTest::newRow("list") << "hough.area_bounds"
                              << QString::fromUtf8("hough.area_bounds: [70, 105, 140, 170, 205, 240] \u2192 [70, 110]");
        QTest::newRow("choice") << "algorithm.method" << QString::fromUtf8("algorithm.method: combined \u2192 opencv");
    }
    void linesSaySavedThenRecovered()
    {
        QFETCH(QString, key);
        QFETCH(QString, line);
        Config recovered;
        recovered.edges.cannyLow = 75;
        recovered.hough.areaBounds = {70, 110};
        recovered.algorithm = Algorithm::OpenCv;
        for (const ConfigChange& c : diffConfigs(Config{}, recovered))
            if (QString::fromStdString(c.key) == key) {
                QCOMPARE(QString::fromStdString(c.toString()), line);
                return;
            }
        QFAIL("the key is not in the diff");
    }
};

QTEST_GUILESS_MAIN(ConfigDiffTest)
#include "calib_config_diff_test.moc"
