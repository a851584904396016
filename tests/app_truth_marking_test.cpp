// Ground-truth marking in the workbench window, offscreen, on a copy of the demo session:
// the marking keys act only in marking mode; a click on the ball marks it with the model's
// radius and moves on; a drag sets the radius; A accepts the detector's result, N marks no
// ball, Delete clears, U finds the next unmarked frame; every mark is in truth.csv at once,
// the file from before marking is kept as truth.csv.bak, and a truth.csv with a broken header
// is never overwritten. Issue 13 bug 1: marking mode never carries over to another source
// (nor turns on where it is refused), a radius far outside the ball model asks first, and
// marks are undone and redone on the window's one undo stack.
#include "core/BallModel.h"
#include "widgets/FrameNavigator.h"
#include "app/MainWindow.h"
#include "widgets/MarkedSlider.h"
#include "widgets/PipelineView.h"
#include "calib/session/TruthCsv.h"
#include "widgets/TruthDocument.h"
#include "widgets/TruthMarker.h"
#include "WindowTestSupport.h"

#include "widgets/ConfigDocument.h"

#include <QAction>
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
        session_ = freshDemo(tmp_);
        QVERIFY(!session_.isEmpty());
        if (!keepTruth) QVERIFY(QFile::remove(truthPath()));
        QVERIFY(openWindow(window_, session_, Shown::AsIs));
    }

private slots:
    void initTestCase()
    {
        startWindowTests();
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
        const QPoint out = widgetPos(220, 200);  // 20 px: inside the ball model's range, no question
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

    void markingModeNeverCarriesOverToAnotherSource()
    {
        open(true);
        const TruthRow original = *window_->truth()->row(0);
        // An image folder (the session's frames): T is refused and the mode stays off.
        QVERIFY(window_->openSource(session_ + "/frames"));
        QVERIFY(waitForFrame(*window_, 0));
        auto* action = window_->findChild<QAction*>("markTruth");
        QTest::keyClick(window_.get(), Qt::Key_T);
        QVERIFY(!window_->truthMarker()->isMarking());
        QVERIFY(!action->isChecked());
        QVERIFY2(window_->findChild<QLabel*>("truth")->text().contains("session"), qPrintable(window_->findChild<QLabel*>("truth")->text()));

        // The session again: not marking, so a left drag pans and the truth stays as it was.
        QVERIFY(window_->openSource(session_));
        QVERIFY(waitForFrame(*window_, 0));
        QVERIFY(!window_->truthMarker()->isMarking());
        window_->pipelineView()->transform()->setZoom(3.0, QPointF(320, 240));
        QTest::mousePress(acquired(), Qt::LeftButton, Qt::NoModifier, widgetPos(300, 200));
        QTest::mouseRelease(acquired(), Qt::LeftButton, Qt::NoModifier, widgetPos(340, 200));
        QCOMPARE(window_->truth()->row(0)->px, original.px);
        QCOMPARE(window_->truth()->row(0)->radiusPx, original.radiusPx);

        // Marking on, then another source: off again, and the menu's check mark with it.
        QTest::keyClick(window_.get(), Qt::Key_T);
        QVERIFY(window_->truthMarker()->isMarking() && action->isChecked());
        QVERIFY(window_->openSource(session_));
        QVERIFY(!window_->truthMarker()->isMarking());
        QVERIFY(!action->isChecked());
        QVERIFY(!window_->findChild<QLabel*>("truth")->text().contains("MARKING"));
    }

    void aRadiusFarOutsideTheBallModelAsksFirst()
    {
        open(true);
        const TruthRow original = *window_->truth()->row(0);
        const double maxRadius = window_->lastRun()->config.ball.maxRadius;
        QTest::keyClick(window_.get(), Qt::Key_T);
        // A drag of about 111 px from (320, 240), as a pan meant in marking mode would be.
        const QPoint centre = widgetPos(320, 240);
        const QPoint out = widgetPos(320 + 111, 240);
        QVERIFY(QLineF(imagePos(centre), imagePos(out)).length() > maxRadius * 1.5);
        QString question;
        answerNextMessageBox(QMessageBox::No, &question);
        QTest::mousePress(acquired(), Qt::LeftButton, Qt::NoModifier, centre);
        QTest::mouseRelease(acquired(), Qt::LeftButton, Qt::NoModifier, out);
        QVERIFY2(question.contains("far outside") && question.contains("25.0 px"), qPrintable(question));
        QCOMPARE(window_->truth()->row(0)->px, original.px);  // "No": the truth is untouched
        QCOMPARE(readTruth(truthPath()).at(0).radiusPx, original.radiusPx);
        QCOMPARE(window_->navigator()->current(), 0);

        answerNextMessageBox(QMessageBox::Yes, nullptr);  // a deliberate large mark is kept
        QTest::mousePress(acquired(), Qt::LeftButton, Qt::NoModifier, centre);
        QTest::mouseRelease(acquired(), Qt::LeftButton, Qt::NoModifier, out);
        QVERIFY(window_->truth()->row(0)->radiusPx > maxRadius * 1.5);
    }

    void marksUndoOnTheWindowsOneStack()
    {
        open(true);
        const TruthRow original = *window_->truth()->row(0);
        QVERIFY(original.ballVisible);
        QUndoStack* stack = window_->document()->undoStack();
        QVERIFY(!window_->document()->setValue("edges.canny_low", ConfigValue(55)));  // a config edit first
        QTest::keyClick(window_.get(), Qt::Key_T);
        QTest::keyClick(window_.get(), Qt::Key_N);  // frame 0: "no ball" replaces the ball
        QCOMPARE(stack->count(), 2);  // one stack for both
        QVERIFY(!readTruth(truthPath()).at(0).ballVisible);
        QVERIFY(waitForFrame(*window_, 1));

        QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);  // undoes the mark, not the edit
        QVERIFY(window_->truth()->row(0)->ballVisible);
        const auto saved = readTruth(truthPath());  // and truth.csv says so again
        QVERIFY(saved.at(0).ballVisible);
        QCOMPARE(saved.at(0).px, original.px);
        QCOMPARE(saved.at(0).radiusPx, original.radiusPx);
        QCOMPARE(window_->navigator()->current(), 0);  // the frame the undo changed is shown
        QVERIFY2(window_->statusBar()->currentMessage().startsWith("Undone \"mark frame 0\": frame 0 is ball at"),
                 qPrintable(window_->statusBar()->currentMessage()));
        QCOMPARE(window_->document()->config().edges.cannyLow, 55);
        QVERIFY(window_->document()->isDirty());

        QTest::keySequence(window_.get(), QKeySequence::Redo);
        QVERIFY(!readTruth(truthPath()).at(0).ballVisible);
        QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
        QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);  // then the config edit
        QCOMPARE(window_->document()->config().edges.cannyLow, 60);
        QVERIFY(!window_->document()->isDirty());  // a mark alone never makes the config unsaved
        QVERIFY(readTruth(truthPath()).at(0).ballVisible);
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
