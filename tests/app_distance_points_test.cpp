// Issue 11, the distance map in the window: points clicked on a pane with their distance
// typed, a fit written as one undo step whose map gives back the known curve, refusals that
// change nothing (too few points, a curve that bends back), points from a CSV, and the camera
// height. The model is checked under QAbstractItemModelTester while it is edited.
#include "app/MainWindow.h"
#include "core/DistanceMap.h"
#include "widgets/ConfigDocument.h"
#include "widgets/DistanceFitPlot.h"
#include "widgets/DistancePointsModel.h"
#include "widgets/DistancePointsPanel.h"
#include "widgets/ImageView.h"
#include "widgets/PaneEditors.h"
#include "widgets/PipelineView.h"
#include "WindowTestSupport.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QtTest>

#include <cmath>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

// The floor as the test's camera sees it: metres at an image radius (monotone, curving up).
double groundAt(double radiusPx) { return 0.004 * radiusPx + 0.00008 * radiusPx * radiusPx; }

}  // namespace

class DistancePointsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        startWindowTests();
        QVERIFY(dir_.isValid());
        QVERIFY(copyDemo(dir_.filePath("demo")));
    }

    void init()
    {
        QVERIFY(openWindow(window_, dir_.filePath("demo"), Shown::Active));
        tester_ = std::make_unique<QAbstractItemModelTester>(panel()->model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    }

    void cleanup()
    {
        tester_.reset();
        if (window_) window_->document()->discardChanges();
        window_.reset();
    }

    void clickedPointsFitTheKnownCurveAsOneStep()
    {
        ConfigDocument* doc = window_->document();
        QVERIFY(!window_->findChild<QDockWidget*>("distanceMap"));  // docked on first use
        window_->findChild<QAction*>("distanceMapPoints")->trigger();
        auto* dock = window_->findChild<QDockWidget*>("distanceMap");
        QVERIFY(dock && dock->isVisible());
        QCOMPARE(dock->widget(), panel());

        const std::vector<double> radiiBefore = doc->config().distanceMap.pixelRadii;
        const GeometryOptions& g = doc->config().geometry;
        const QPointF centre(g.centerX, g.centerY);
        ImageView* pane = window_->pipelineView()->pane(PipelineView::Acquired);
        // The typed distance is the test camera's, at the radius the pane reported.
        panel()->setDistanceAsker([&](QPointF p) -> std::optional<double> {
            return groundAt(std::hypot(p.x() - centre.x(), p.y() - centre.y()));
        });
        QTest::mouseClick(panel()->findChild<QPushButton*>("addDistancePoints"), Qt::LeftButton);
        QVERIFY(panel()->isAdding());
        const int steps = doc->undoStack()->count();
        for (int i = 0; i < 8; ++i) {
            const double r = 60 + 22 * i, a = 0.7 * i;  // spread over radii and directions
            QTest::mouseClick(pane, Qt::LeftButton, {}, pane->toWidget(centre + r * QPointF(std::cos(a), std::sin(a))).toPoint());
        }
        QCOMPARE(panel()->model()->rowCount(), 8);
        QCOMPARE(doc->undoStack()->count(), steps);  // points are not config edits

        QTest::mouseClick(panel()->findChild<QPushButton*>("fitDistanceMap"), Qt::LeftButton);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY2(panel()->status().contains("RMS"), qPrintable(panel()->status()));
        const DistanceMap map(doc->config().distanceMap);
        for (double r : {70.0, 120.0, 180.0, 210.0})
            QVERIFY2(std::abs(map.toGround(r) - groundAt(r)) < 0.01, qPrintable(QString("at %1 px: %2 m").arg(r).arg(map.toGround(r))));
        QVERIFY(panel()->plot()->fit());
        if (qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR"))  // to look at the points, the tab and the plot
            window_->grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/distance-map.png");
        QVERIFY(panel()->plot()->fit()->rmsCm < 1.0);
        QVERIFY(!panel()->model()->data(panel()->model()->index(0, DistancePointsModel::Residual)).toString().isEmpty());

        doc->undoStack()->undo();
        QCOMPARE(doc->config().distanceMap.pixelRadii, radiiBefore);
        QVERIFY(!doc->isDirty());

        // Escape ends adding; the left button pans again.
        QTest::keyClick(window_.get(), Qt::Key_Escape);
        QVERIFY(!panel()->isAdding());
        QCOMPARE(window_->pipelineView()->paneEditor(), nullptr);
    }

    void refusedFitsChangeNothing()
    {
        ConfigDocument* doc = window_->document();
        const std::vector<double> before = doc->config().distanceMap.groundDistances;
        const QString few = writeCsv("few.csv", "radius_px,distance_m\n50,0.3\n100,0.9\n");
        QVERIFY(panel()->loadPoints(few));
        QCOMPARE(panel()->model()->rowCount(), 2);
        const int steps = doc->undoStack()->count();
        QVERIFY(!panel()->fit());
        QVERIFY2(panel()->status().contains("needs at least"), qPrintable(panel()->status()));
        // Distances that rise, then fall: the fit bends back and is refused, saying where.
        const QString bent = writeCsv("bent.csv", "radius_px,distance_m\n40,0.2\n60,0.6\n80,1.2\n100,2.0\n120,1.0\n140,0.5\n160,0.3\n180,0.2\n");
        QVERIFY(panel()->loadPoints(bent));
        QVERIFY(!panel()->fit());
        QVERIFY2(panel()->status().contains("not monotone"), qPrintable(panel()->status()));
        QCOMPARE(doc->undoStack()->count(), steps);
        QCOMPARE(doc->config().distanceMap.groundDistances, before);
        // A file that cannot be used keeps the points there are, and names itself.
        QVERIFY(!panel()->loadPoints(writeCsv("nonsense.csv", "a,b\n1,2\n")));
        QVERIFY2(panel()->status().contains("nonsense.csv"), qPrintable(panel()->status()));
        QCOMPARE(panel()->model()->rowCount(), 8);
        panel()->model()->removePoint(0);
        QCOMPARE(panel()->model()->rowCount(), 7);
    }

    void cameraHeightIsAConfigEdit()
    {
        ConfigDocument* doc = window_->document();
        auto* height = panel()->findChild<QDoubleSpinBox*>("viewpointHeight");
        QVERIFY(height);
        QCOMPARE(height->value(), doc->config().distanceMap.viewpointHeight);
        const int steps = doc->undoStack()->count();
        height->setValue(0.82);
        QCOMPARE(doc->config().distanceMap.viewpointHeight, 0.82);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        doc->undoStack()->undo();
        QCOMPARE(height->value(), doc->config().distanceMap.viewpointHeight);  // the box follows the undo
    }

private:
    DistancePointsPanel* panel() const { return window_->paneEditors()->distances(); }
    QString writeCsv(const QString& name, const QByteArray& text)
    {
        QFile f(dir_.filePath(name));
        if (!f.open(QIODevice::WriteOnly)) return {};
        f.write(text);
        return f.fileName();
    }

    QTemporaryDir dir_;
    std::unique_ptr<MainWindow> window_;
    std::unique_ptr<QAbstractItemModelTester> tester_;
};

QTEST_MAIN(DistancePointsTest)
#include "app_distance_points_test.moc"
