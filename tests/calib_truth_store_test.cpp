// The ground truth apart from any window (calib/session): TruthStore opens a missing file as
// an empty truth, refuses a header it cannot use, saves every change at once and keeps a
// failed one in memory; TruthMarkRules measures a clicked ball with the config's models and
// says when a hand-set radius is far outside the ball model.
#include "calib/session/TruthMarkRules.h"
#include "calib/session/TruthStore.h"
#include "core/BallModel.h"

#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <sstream>

using namespace omnitune;

namespace {
std::string readAll(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
}  // namespace

class TruthStoreTest : public QObject {
    Q_OBJECT
private slots:
    void missingFileIsAnEmptyTruthAndEveryChangeIsSaved()
    {
        QTemporaryDir dir;
        TruthStore store;
        QVERIFY(!store.isOpen());
        QVERIFY(!store.closedReason().empty());
        QVERIFY(!store.open(dir.path().toStdString()));
        QVERIFY(store.isOpen() && store.rows().empty());
        TruthRow row;
        row.frame = 3;
        row.ballVisible = true;
        row.px = 10;
        row.py = 20;
        row.radiusPx = 5;
        bool changed = false;
        QVERIFY(!store.set(row, true, &changed));
        QVERIFY(changed);
        const TruthParse saved = parseTruthCsv(readAll(store.path()), store.path());
        QVERIFY(saved.ok() && saved.rows.count(3) == 1 && saved.rows.at(3).px == 10);
        QVERIFY(!store.remove(4, true, &changed));
        QVERIFY(!changed);  // nothing to remove
        QVERIFY(!store.remove(3, true, &changed));
        QVERIFY(changed && parseTruthCsv(readAll(store.path()), store.path()).rows.empty());
    }

    void unusableHeaderIsRefused()
    {
        QTemporaryDir dir;
        std::ofstream(dir.filePath("truth.csv").toStdString()) << "not,a,truth header\n1,2,3\n";
        TruthStore store;
        const auto why = store.open(dir.path().toStdString());
        QVERIFY(why && why->find("fix or remove") != std::string::npos);
        QVERIFY(!store.isOpen());
        QVERIFY(store.set(TruthRow{}, true).has_value());  // refused, nothing written
        QCOMPARE(readAll(dir.filePath("truth.csv").toStdString()), std::string("not,a,truth header\n1,2,3\n"));
    }

    void failedSaveKeepsTheRowInMemory()
    {
        QTemporaryDir dir;
        TruthStore store;
        QVERIFY(!store.open(dir.filePath("no-such-folder").toStdString()));
        const auto err = store.set(TruthRow{}, false);
        QVERIFY(err && err->find("kept in memory") != std::string::npos);
        QVERIFY(store.hasUnsavedRows() && store.row(0));
    }

    void radiusFarFromTheModel_data()
    {
        QTest::addColumn<double>("radius");
        QTest::addColumn<bool>("far");
        // thesis defaults: 3-25 px, far beyond x1.5 either way
        QTest::newRow("model radius") << 12.0 << false;
        QTest::newRow("a little above max") << 30.0 << false;
        QTest::newRow("at the limit") << 37.5 << false;
        QTest::newRow("a pan-drag (issue 13)") << 111.0 << true;
        QTest::newRow("a little below min") << 2.5 << false;
        QTest::newRow("far below min") << 1.0 << true;
    }
    void radiusFarFromTheModel()
    {
        QFETCH(double, radius);
        QFETCH(bool, far);
        const auto why = radiusFarFromModel(radius, BallModelOptions{});
        QCOMPARE(why.has_value(), far);
        if (far) QVERIFY(why->find("ball.max_radius") != std::string::npos);
    }

    void clickedBallIsMeasuredWithTheConfig()
    {
        const Config c;
        TruthRow row;
        const cv::Size size(c.geometry.imageWidth, c.geometry.imageHeight);
        QVERIFY(makeBallMark(c, size, 2, -1, 10, 0, row).has_value());  // outside the image
        const double x = c.geometry.centerX + 100, y = c.geometry.centerY;
        QVERIFY(!makeBallMark(c, size, 2, x, y, 0, row));
        QCOMPARE(row.frame, 2);
        QCOMPARE(row.radiusPx, BallModel(c.ball).radiusAt(100));  // a click: the model's radius
        QVERIFY(row.xM > 0 && std::abs(row.yM) < 1e-9);  // to the robot's right
        QVERIFY(!makeBallMark(c, size, 2, x, y, 14, row));
        QCOMPARE(row.radiusPx, 14.0);  // a drag: the hand's
        BallDetection none;
        QVERIFY(!detectionMark(5, none).ballVisible);
    }
};

QTEST_GUILESS_MAIN(TruthStoreTest)
#include "calib_truth_store_test.moc"
