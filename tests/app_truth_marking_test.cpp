// Ground-truth marking in the workbench window, offscreen, on a copy of the demo session:
// the marking keys act only in marking mode; a click on the ball marks it with the model's
// radius and moves on; a drag sets the radius; A accepts the detector's result, N marks no
// ball, Delete clears, U finds the next unmarked frame; every mark is in truth.csv at once,
// the file from before marking is kept as truth.csv.bak, and a truth.csv with a broken header
// is never overwritten.
#include "core/BallModel.h"
#include "widgets/FrameNavigator.h"
#include "app/MainWindow.h"
#include "widgets/MarkedSlider.h"
#include "widgets/PipelineView.h"
#include "calib/session/TruthCsv.h"
#include "widgets/TruthDocument.h"
#include "widgets/TruthMarker.h"
#include "WindowTestSupport.h"

#include <QLabel>
#include <QStatusBar>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

std::map<int, TruthRow> readTruth(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return parseTruthCsv(f.readAll().toStdString(), path.toStdString()).rows;
}

QByteArray fileBytes(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TruthMarkingTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    QString session_;
    std::unique_ptr<MainWindow> window_;

    QString truthPath() const { return session_ + "/truth.csv"; }
    ImageView* acquired() const { return window_->pipelineView()->pane(PipelineView::Acquired); }
    QPoint widgetPos(double x, double y) const { return acquired()->toWidget(QPointF(x, y)).toPoint(); }
    QPointF imagePos(QPoint w) const { return acquired()->toImage(QPointF(w)); }

    void open(bool keepTruth)
    {
        session_ = tmp_.filePath(QStringLiteral("demo-%1").arg(QDateTime::currentMSecsSinceEpoch()));
        QVERIFY(copyDemo(session_));
        if (!keepTruth) QVERIFY(QFile::remove(truthPath()));
        window_ = std::make_unique<MainWindow>();
        window_->show();
        QVERIFY(window_->openSource(session_));
        QVERIFY(waitForFrame(*window_, 0));
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);  // recent files: not the user's settings
        QSettings().clear();
    }
    void cleanup() { window_.reset(); }

    void keysDoNothingOutsideMarkingMode()
    {
        open(false);
        QTest::keyClick(window_.get(), Qt::Key_N);
        QTest::keyClick(window_.get(), Qt::Key_A);
        QVERIFY(window_->truth()->rows().empty());
        QVERIFY(!QFile::exists(truthPath()));
        QVERIFY(!window_->truth()->set(TruthRow{}));  // frame 0: "no ball", by hand
        QTest::keyClick(window_.get(), Qt::Key_Delete);
        QTest::keyClick(window_.get(), Qt::Key_U);
        QVERIFY(window_->truth()->row(0));
        QCOMPARE(window_->navigator()->current(), 0);
        auto* banner = window_->findChild<QLabel*>("truth");
        QVERIFY(!banner->text().contains("MARKING"));
        QTest::keyClick(window_.get(), Qt::Key_T);
        QVERIFY(window_->truthMarker()->isMarking());
        QVERIFY(banner->text().contains("MARKING TRUTH"));  // the mode cannot be missed
        QTest::keyClick(window_.get(), Qt::Key_T);
        QVERIFY(!window_->truthMarker()->isMarking());
        QVERIFY(!banner->text().contains("MARKING"));
    }

    void keysMarkAndAdvance()
    {
        open(false);
        QTest::keyClick(window_.get(), Qt::Key_T);
        QVERIFY(window_->lastRun()->result.detection.found);
        const BallDetection detected = window_->lastRun()->result.detection;

        QTest::keyClick(window_.get(), Qt::Key_A);  // frame 0: the detector's ball
        QCOMPARE(window_->navigator()->current(), 1);
        QVERIFY(waitForFrame(*window_, 1));
        QTest::keyClick(window_.get(), Qt::Key_N);  // frame 1: "no ball"
        QCOMPARE(window_->navigator()->current(), 2);
        QVERIFY2(window_->statusBar()->currentMessage().startsWith("Frame 1: no ball, saved to truth.csv"),
                 qPrintable(window_->statusBar()->currentMessage()));

        const auto rows = readTruth(truthPath());  // already on disk
        QCOMPARE(int(rows.size()), 2);
        QVERIFY(rows.at(0).ballVisible);
        QCOMPARE(rows.at(0).px, detected.px);
        QCOMPARE(rows.at(0).radiusPx, detected.radiusPx);
        QCOMPARE(rows.at(0).yM, detected.yM);
        QVERIFY(!rows.at(1).ballVisible);
        QVERIFY(window_->findChild<QLabel*>("truth")->text().contains("2 of 24"));
        QCOMPARE(window_->navigator()->slider()->marks(FrameMarkKind::Truth).size(), 2);

        QTest::keyClick(window_.get(), Qt::Key_Home);
        QTest::keyClick(window_.get(), Qt::Key_U);  // next unmarked after 0 is 2
        QCOMPARE(window_->navigator()->current(), 2);
        QTest::keyClick(window_.get(), Qt::Key_Left);
        QCOMPARE(window_->navigator()->current(), 1);
        QTest::keyClick(window_.get(), Qt::Key_Delete);
        QCOMPARE(int(readTruth(truthPath()).size()), 1);
        QVERIFY(!window_->truth()->row(1));
        QVERIFY(!window_->navigator()->slider()->hasMark(1, FrameMarkKind::Truth));
    }

    void clickMarksWithTheModelRadiusAndDragSetsIt()
    {
        open(false);
        QTest::keyClick(window_.get(), Qt::Key_T);
        const Config config = window_->lastRun()->config;
        const BallDetection d = window_->lastRun()->result.detection;
        QVERIFY(d.found);

        const QPoint at = widgetPos(d.px, d.py);
        QTest::mouseClick(acquired(), Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(window_->navigator()->current(), 1);
        // Frame 1 is asked for but the panes still show frame 0: a second quick click (or a
        // double click) must not give frame 1 frame 0's ball.
        QVERIFY(window_->lastRun()->frameIndex == 0);
        QTest::mouseClick(acquired(), Qt::LeftButton, Qt::NoModifier, at);
        QVERIFY(!window_->truth()->row(1));
        QCOMPARE(window_->navigator()->current(), 1);
        const TruthRow* clicked = window_->truth()->row(0);
        QVERIFY(clicked && clicked->ballVisible);
        const QPointF where = imagePos(at);  // the click lands on a whole widget pixel
        QCOMPARE(clicked->px, where.x());
        QCOMPARE(clicked->py, where.y());
        const double distance = std::hypot(where.x() - config.geometry.centerX, where.y() - config.geometry.centerY);
        QCOMPARE(clicked->radiusPx, BallModel(config.ball).radiusAt(distance));
        QVERIFY(std::hypot(clicked->xM - d.xM, clicked->yM - d.yM) < 0.1);

        // Frame 1: press on a centre, drag 40 widget px out, release: the radius follows.
        QVERIFY(waitForFrame(*window_, 1));
        QTest::mouseClick(acquired(), Qt::LeftButton, Qt::NoModifier, widgetPos(-20, 100));  // off the image
        QVERIFY(!window_->truth()->row(1));
        const QPoint centre = widgetPos(200, 200);
        const QPoint out = centre + QPoint(40, 0);
        QTest::mousePress(acquired(), Qt::LeftButton, Qt::NoModifier, centre);
        QMouseEvent move(QEvent::MouseMove, out, acquired()->mapToGlobal(out), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(acquired(), &move);
        QTest::mouseRelease(acquired(), Qt::LeftButton, Qt::NoModifier, out);
        const TruthRow* dragged = window_->truth()->row(1);
        QVERIFY(dragged && dragged->ballVisible);
        const double expected = QLineF(imagePos(centre), imagePos(out)).length();
        QVERIFY2(std::abs(dragged->radiusPx - expected) < 1e-6, qPrintable(QString::number(dragged->radiusPx)));
        QCOMPARE(window_->navigator()->current(), 2);
    }

    void keepsThePreviousFileAsBackupAndReloads()
    {
        open(true);  // the demo's own truth.csv, recorded with robot poses
        const QByteArray original = fileBytes(truthPath());
        QVERIFY(window_->truth()->row(0) && window_->truth()->row(0)->robot);
        QTest::keyClick(window_.get(), Qt::Key_T);
        QTest::keyClick(window_.get(), Qt::Key_N);
        QVERIFY(waitForFrame(*window_, 1));
        QTest::keyClick(window_.get(), Qt::Key_N);
        QCOMPARE(fileBytes(truthPath() + ".bak"), original);  // the second save kept the first backup
        const auto rows = readTruth(truthPath());
        QVERIFY(!rows.at(0).ballVisible && !rows.at(1).ballVisible);
        QVERIFY(rows.at(0).robot.has_value());  // the recorded pose stays with the frame
        QCOMPARE(rows.size(), std::size_t(24));

        window_.reset();
        window_ = std::make_unique<MainWindow>();
        window_->show();
        QVERIFY(window_->openSource(session_));
        QVERIFY(waitForFrame(*window_, 0));
        QVERIFY(window_->truth()->row(1) && !window_->truth()->row(1)->ballVisible);
        QTest::keyClick(window_.get(), Qt::Key_End);
        QVERIFY(waitForFrame(*window_, 23));
        QTest::keyClick(window_.get(), Qt::Key_T);
        QTest::keyClick(window_.get(), Qt::Key_N);  // reopened and marked again: still the original backup
        QVERIFY(!readTruth(truthPath()).at(23).ballVisible);
        QCOMPARE(fileBytes(truthPath() + ".bak"), original);
        QCOMPARE(window_->navigator()->slider()->marks(FrameMarkKind::Truth).size(), 24);  // the loaded file marks the slider
    }

    void theLastFrameIsMarkedWithoutGoingRound()
    {
        open(false);
        QTest::keyClick(window_.get(), Qt::Key_End);
        QVERIFY(waitForFrame(*window_, 23));
        QTest::keyClick(window_.get(), Qt::Key_T);
        QTest::keyClick(window_.get(), Qt::Key_N);
        QVERIFY(window_->truth()->row(23));
        QCOMPARE(window_->navigator()->current(), 23);  // loop is on, yet marking stops here
    }

    void brokenTruthFileIsNeverOverwritten()
    {
        open(true);
        window_.reset();
        QFile f(truthPath());
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("this is not,a truth header\n1,2\n");
        f.close();
        window_ = std::make_unique<MainWindow>();
        window_->show();
        QVERIFY(window_->openSource(session_));
        QVERIFY(waitForFrame(*window_, 0));
        QVERIFY(!window_->truth()->isOpen());
        QTest::keyClick(window_.get(), Qt::Key_T);
        QTest::keyClick(window_.get(), Qt::Key_N);
        QCOMPARE(fileBytes(truthPath()), QByteArray("this is not,a truth header\n1,2\n"));
        QVERIFY(window_->findChild<QLabel*>("truth")->text().contains("fix or remove"));
    }
};

QTEST_MAIN(TruthMarkingTest)
#include "app_truth_marking_test.moc"
