// Issue 11, the robot mask editor: on the real window and its panes, driven by QTest events.
// A brush stroke changes exactly the pixels within the brush of its path and one Ctrl+Z gives
// them back; a polygon and a fill paint what they enclose; Escape drops a polygon, then leaves
// the mode; saving writes the mask beside config.yml (atomically: no temporary left) and the
// config reloads with the same pixels. The demo session has no mask: the editor starts one.
#include "app/MainWindow.h"
#include "calib/mask/MaskPaint.h"
#include "core/ConfigParser.h"
#include "widgets/ConfigDocument.h"
#include "widgets/GeometryEditor.h"
#include "widgets/ImageView.h"
#include "widgets/MaskEditor.h"
#include "widgets/MaskImportDialog.h"
#include "widgets/PaneEditors.h"
#include "widgets/PipelineView.h"
#include "widgets/PipelineRunner.h"
#include "WindowTestSupport.h"

#include <opencv2/imgcodecs.hpp>

#include <QDialogButtonBox>
#include <QDir>
#include <QMouseEvent>
#include <QApplication>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QStatusBar>
#include <QToolBar>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

int differing(const cv::Mat& a, const cv::Mat& b)
{
    if (a.size() != b.size()) return -1;
    return cv::countNonZero(a != b);
}

// The mask the panes show: the last run's (the tint is built from it on the runner's thread).
bool waitForMask(MainWindow& window, const cv::Mat& mask)
{
    QSignalSpy spy(&window, &MainWindow::runShown);
    for (int i = 0; i < 50; ++i) {
        const auto run = window.lastRun();
        if (!window.isProcessing() && run && run->maskTint && differing(run->config.mask, mask) == 0) return true;
        spy.wait(200);
    }
    return false;
}

}  // namespace

class MaskEditorTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        startWindowTests();
        QVERIFY(dir_.isValid());
    }

    void init()
    {
        session_ = freshDemo(dir_);
        QVERIFY(!session_.isEmpty());
        QVERIFY(openWindow(window_, session_, Shown::Active));
        QTest::keyClick(window_.get(), Qt::Key_M);
        QVERIFY(editor()->isEditing());
        QVERIFY(editor()->toolBar()->isVisible());
    }

    void cleanup()
    {
        if (window_) window_->document()->discardChanges();  // closing must not ask
        window_.reset();
    }

    void brushChangesExactlyTheBrushedPixelsAndUndoes()
    {
        ConfigDocument* doc = window_->document();
        QVERIFY(doc->config().mask.empty());
        const GeometryOptions& g = doc->config().geometry;
        const cv::Mat before(g.imageHeight, g.imageWidth, CV_8UC1, cv::Scalar(kMaskProcessed));
        editor()->setBrushRadius(4.0);
        ImageView* pane = acquired();
        const QPoint a = pane->toWidget(QPointF(g.centerX + 80.3, g.centerY - 40.6)).toPoint();
        const QPoint b = pane->toWidget(QPointF(g.centerX + 140.2, g.centerY + 10.1)).toPoint();
        const int steps = doc->undoStack()->count();
        QTest::mousePress(pane, Qt::LeftButton, {}, a);
        QTest::mouseMove(pane, b);
        QVERIFY(!doc->config().mask.empty());  // live while dragging
        QTest::mouseRelease(pane, Qt::LeftButton, {}, b);
        QCOMPARE(doc->undoStack()->count(), steps + 1);  // the whole stroke is one step
        QVERIFY(doc->isDirty());
        QCOMPARE(QString::fromStdString(doc->config().geometry.maskFile), QStringLiteral("mask.png"));

        // What the brush covers: every pixel whose centre is within 4 px of the path.
        cv::Mat expected = before.clone();
        const QPointF ia = pane->toImage(a), ib = pane->toImage(b);
        const int brushed = paintStroke(expected, {ia.x(), ia.y()}, {ib.x(), ib.y()}, 4.0, kMaskRobot);
        QVERIFY(brushed > 8 * 60);  // a 60 px long, 8 px wide band
        QCOMPARE(differing(doc->config().mask, expected), 0);
        QCOMPARE(differing(doc->config().mask, before), brushed);
        // The tint on the panes comes from that mask.
        QVERIFY(waitForMask(*window_, expected));
        const QImage& tint = *window_->lastRun()->maskTint;
        const QPointF mid = (ia + ib) / 2;
        QVERIFY(qAlpha(tint.pixel(int(mid.x()), int(mid.y()))) > 0);
        QCOMPARE(qAlpha(tint.pixel(int(g.centerX - 100), int(g.centerY))), 0);
        if (qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR")) {  // docs/images/mask-editor.png
            editor()->setBrushRadius(10.0);
            QTest::mouseMove(pane, pane->toWidget(QPointF(g.centerX + 150, g.centerY + 40)).toPoint());
            window_->grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/mask-editor.png");
            editor()->setBrushRadius(4.0);
        }

        // Erasing across half of the band gives those pixels back, again one step.
        QTest::keyClick(window_.get(), Qt::Key_E);
        QCOMPARE(editor()->tool(), MaskEditor::Tool::Eraser);
        QTest::mousePress(pane, Qt::LeftButton, {}, a);
        QTest::mouseRelease(pane, Qt::LeftButton, {}, a);
        cv::Mat erased = expected.clone();
        QVERIFY(paintStroke(erased, {ia.x(), ia.y()}, {ia.x(), ia.y()}, 4.0, kMaskProcessed) > 20);
        QCOMPARE(differing(doc->config().mask, erased), 0);
        QCOMPARE(doc->undoStack()->count(), steps + 2);

        doc->undoStack()->undo();
        QCOMPARE(differing(doc->config().mask, expected), 0);
        doc->undoStack()->undo();
        QVERIFY(doc->config().mask.empty());  // as before the first stroke
        QVERIFY(!doc->isDirty());
        doc->undoStack()->redo();
        QCOMPARE(differing(doc->config().mask, expected), 0);
    }

    void brushSizeFromKeysAndCtrlWheel()
    {
        editor()->setBrushRadius(5.0);
        QTest::keyClick(window_.get(), Qt::Key_BracketRight);
        QCOMPARE(editor()->brushRadius(), 6.0);
        QTest::keyClick(window_.get(), Qt::Key_BracketLeft);
        QTest::keyClick(window_.get(), Qt::Key_BracketLeft);
        QCOMPARE(editor()->brushRadius(), 4.0);
        ImageView* pane = acquired();
        const double zoom = pane->scale();
        const QPointF at(pane->width() / 2.0, pane->height() / 2.0);
        QWheelEvent up(at, pane->mapToGlobal(at.toPoint()), QPoint(), QPoint(0, 240), Qt::NoButton, Qt::ControlModifier,
                       Qt::NoScrollPhase, false);
        QApplication::sendEvent(pane, &up);
        QCOMPARE(editor()->brushRadius(), 6.0);
        QCOMPARE(pane->scale(), zoom);  // Ctrl+wheel sizes the brush, it does not zoom
    }

    void polygonAndFill()
    {
        ConfigDocument* doc = window_->document();
        const GeometryOptions& g = doc->config().geometry;
        ImageView* pane = acquired();
        QTest::keyClick(window_.get(), Qt::Key_P);
        QCOMPARE(editor()->tool(), MaskEditor::Tool::Polygon);
        const QPointF corners[] = {{g.centerX + 90, g.centerY + 60}, {g.centerX + 170, g.centerY + 70},
                                   {g.centerX + 150, g.centerY + 150}, {g.centerX + 80, g.centerY + 130}};
        std::vector<cv::Point2d> vertices;
        const int steps = doc->undoStack()->count();
        for (const QPointF& c : corners) {
            const QPoint w = pane->toWidget(c).toPoint();
            QTest::mouseClick(pane, Qt::LeftButton, {}, w);
            vertices.emplace_back(pane->toImage(w).x(), pane->toImage(w).y());
        }
        QCOMPARE(int(editor()->polygon().size()), 4);
        QCOMPARE(doc->undoStack()->count(), steps);  // nothing painted until it is closed
        QTest::keyClick(window_.get(), Qt::Key_Return);
        QVERIFY(editor()->polygon().empty());
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        cv::Mat expected(g.imageHeight, g.imageWidth, CV_8UC1, cv::Scalar(kMaskProcessed));
        QVERIFY(fillPolygon(expected, vertices, kMaskRobot) > 4000);
        QCOMPARE(differing(doc->config().mask, expected), 0);

        // Filled back as processed, the region is gone again: one step.
        QTest::keyClick(window_.get(), Qt::Key_L);
        QTest::keyClick(window_.get(), Qt::Key_X);  // areas paint "processed"
        QVERIFY(!editor()->areasAsRobot());
        QTest::mouseClick(pane, Qt::LeftButton, {}, pane->toWidget(QPointF(g.centerX + 125, g.centerY + 100)).toPoint());
        QCOMPARE(cv::countNonZero(doc->config().mask), g.imageWidth * g.imageHeight);
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        doc->undoStack()->undo();
        QCOMPARE(differing(doc->config().mask, expected), 0);

        // A double-click closes a polygon too; its processed triangle cuts into the robot region.
        QTest::keyClick(window_.get(), Qt::Key_P);
        const QPointF tri[] = {{g.centerX + 60, g.centerY + 100}, {g.centerX + 120, g.centerY + 40}, {g.centerX + 125, g.centerY + 110}};
        std::vector<cv::Point2d> triangle;
        for (int i = 0; i < 3; ++i) {
            const QPoint w = pane->toWidget(tri[i]).toPoint();
            QTest::mouseClick(pane, Qt::LeftButton, {}, w);
            if (i == 2) QTest::mouseDClick(pane, Qt::LeftButton, {}, w);
            triangle.emplace_back(pane->toImage(w).x(), pane->toImage(w).y());
        }
        QVERIFY(editor()->polygon().empty());
        QVERIFY(fillPolygon(expected, triangle, kMaskProcessed) > 100);
        QCOMPARE(differing(doc->config().mask, expected), 0);

        // Escape drops an open polygon first, then leaves the mode; the panes pan again.
        QTest::mouseClick(pane, Qt::LeftButton, {}, pane->toWidget(QPointF(g.centerX, g.centerY + 200)).toPoint());
        QCOMPARE(int(editor()->polygon().size()), 1);
        QTest::keyClick(window_.get(), Qt::Key_Escape);
        QVERIFY(editor()->polygon().empty());
        QVERIFY(editor()->isEditing());
        QTest::keyClick(window_.get(), Qt::Key_Escape);
        QVERIFY(!editor()->isEditing());
        QVERIFY(!editor()->toolBar()->isVisible());
        const int now = doc->undoStack()->count();
        QTest::mouseClick(pane, Qt::LeftButton, {}, pane->toWidget(QPointF(g.centerX + 125, g.centerY + 100)).toPoint());
        QCOMPARE(doc->undoStack()->count(), now);
    }

    void geometryDragCancelledWhenAnotherEditorTakesOver()
    {
        QTest::keyClick(window_.get(), Qt::Key_G);
        QVERIFY(window_->geometryEditor()->isEditing());
        ConfigDocument* doc = window_->document();
        const GeometryOptions g = doc->config().geometry;
        const int steps = doc->undoStack()->count();
        const QPoint c = acquired()->toWidget(QPointF(g.centerX, g.centerY)).toPoint();
        const QPoint to = acquired()->toWidget(QPointF(g.centerX + 12, g.centerY - 8)).toPoint();
        QTest::mousePress(acquired(), Qt::LeftButton, {}, c);
        // A move with the button held, sent to the pane itself (QTest::mouseMove goes through the
        // cursor, which the offscreen platform delivers without the button).
        QMouseEvent move(QEvent::MouseMove, QPointF(to), QPointF(acquired()->mapToGlobal(to)), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(acquired(), &move);
        QVERIFY(doc->config().geometry.centerY < g.centerY - 4);  // the panes follow the drag live
        QTest::keyClick(window_.get(), Qt::Key_M);            // the mask editor takes the button mid-drag
        QVERIFY(!window_->geometryEditor()->isEditing());
        QCOMPARE(doc->config().geometry.centerY, g.centerY);  // the drag is cancelled, not left half-applied
        QCOMPARE(doc->undoStack()->count(), steps);
        QTest::mouseRelease(acquired(), Qt::LeftButton, {}, to);
        QCOMPARE(doc->config().geometry.centerY, g.centerY);
        QTest::keyClick(window_.get(), Qt::Key_Escape);
    }

    void oneEditorHoldsTheLeftButton()
    {
        QTest::keyClick(window_.get(), Qt::Key_G);
        QVERIFY(window_->geometryEditor()->isEditing());
        QVERIFY(!editor()->isEditing());
        QTest::keyClick(window_.get(), Qt::Key_M);
        QVERIFY(editor()->isEditing());
        QVERIFY(!window_->geometryEditor()->isEditing());
        // A press in mask mode paints; it never drags the centre.
        const GeometryOptions g = window_->document()->config().geometry;
        const QPoint c = acquired()->toWidget(QPointF(g.centerX, g.centerY)).toPoint();
        const QPoint to = c + QPoint(30, 0);
        QTest::mousePress(acquired(), Qt::LeftButton, {}, c);
        // The move with the button held, sent to the pane itself (QTest::mouseMove goes through the
        // cursor, which the offscreen platform delivers without the button: the press alone painted).
        QMouseEvent move(QEvent::MouseMove, QPointF(to), QPointF(acquired()->mapToGlobal(to)), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(acquired(), &move);
        const QPointF end = acquired()->toImage(QPointF(to));
        QCOMPARE(int(window_->document()->config().mask.at<uchar>(int(end.y()), int(end.x()))), int(kMaskRobot));  // painted live
        QCOMPARE(window_->document()->config().geometry.centerX, g.centerX);  // the centre did not follow
        QTest::mouseRelease(acquired(), Qt::LeftButton, {}, to);
        QCOMPARE(window_->document()->config().geometry.centerX, g.centerX);
        QVERIFY(!window_->document()->config().mask.empty());
    }

    void saveWritesTheMaskBesideTheConfigAndItReloads()
    {
        ConfigDocument* doc = window_->document();
        const GeometryOptions& g = doc->config().geometry;
        ImageView* pane = acquired();
        editor()->setBrushRadius(6.0);
        const QPoint a = pane->toWidget(QPointF(g.centerX - 120, g.centerY - 30)).toPoint();
        QTest::mousePress(pane, Qt::LeftButton, {}, a);
        QTest::mouseMove(pane, a + QPoint(25, 25));
        QTest::mouseRelease(pane, Qt::LeftButton, {}, a + QPoint(25, 25));
        const cv::Mat painted = doc->config().mask.clone();
        QVERIFY(cv::countNonZero(painted) < painted.rows * painted.cols);
        QVERIFY(window_->saveConfig());
        QVERIFY(!doc->isDirty());

        const QString config = session_ + "/config.yml";
        QCOMPARE(doc->path(), config);
        const cv::Mat onDisk = cv::imread((session_ + "/mask.png").toStdString(), cv::IMREAD_UNCHANGED);
        QCOMPARE(differing(onDisk, painted), 0);
        QVERIFY(QDir(session_).entryList({"*.tmp"}, QDir::Files | QDir::Hidden).isEmpty());  // nothing half written
        const ConfigLoad reloaded = loadConfig(config.toStdString());
        QVERIFY2(reloaded.ok(), reloaded.ok() ? "" : reloaded.error->toString().c_str());
        QCOMPARE(reloaded.config.geometry.maskFile, std::string("mask.png"));
        QCOMPARE(differing(reloaded.config.mask, painted), 0);

        // Reverting reads it back identical; a new stroke after the save is an edit again.
        QVERIFY(!doc->revert());
        QCOMPARE(differing(doc->config().mask, painted), 0);
        QVERIFY(!doc->isDirty());
        QVERIFY(editor()->isEditing());  // saving and reverting leave the editor on
        QTest::mouseClick(pane, Qt::LeftButton, {}, pane->toWidget(QPointF(g.centerX + 100, g.centerY)).toPoint());
        // Dirty although config and saved config shared one mask buffer after the revert: the
        // click painted into a copy (painting into the shared buffer would look unchanged).
        QVERIFY(doc->isDirty());
    }

    // Another team's mask, red rods on black (black = process): the preview shows the field
    // tinted until "black means process" is chosen, and accepting is one undo step.
    void importedInvertedMaskPreviewsAndAccepts()
    {
        ConfigDocument* doc = window_->document();
        const GeometryOptions& g = doc->config().geometry;
        cv::Mat file(g.imageHeight, g.imageWidth, CV_8UC3, cv::Scalar(0, 0, 0));
        const cv::Rect rod(int(g.centerX) - 6, 0, 12, int(g.centerY));
        file(rod).setTo(cv::Scalar(0, 0, 255));
        const QString path = dir_.filePath("team-mask.png");
        QVERIFY(cv::imwrite(path.toStdString(), file));
        QTest::keyClick(window_.get(), Qt::Key_Escape);  // the import works in or out of the editor

        window_->findChild<QAction*>("importMask")->trigger();
        auto* dialog = window_->findChild<MaskImportDialog*>();
        QVERIFY(dialog && dialog->isVisible());
        QPushButton* ok = dialog->buttons()->button(QDialogButtonBox::Ok);
        QVERIFY(!ok->isEnabled());  // no file yet
        dialog->setFile(path);
        const QPoint field(int(g.centerX), int(g.centerY + 120)), onRod(int(g.centerX), int(g.centerY - 120));
        const QImage frame = toQImage(window_->lastRun()->result.stages.acquired);
        // White means process (the default): the black field is what would be left out.
        QVERIFY(dialog->preview().pixel(field) != frame.pixel(field));
        QCOMPARE(dialog->preview().pixel(onRod), frame.pixel(onRod));
        if (qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR"))  // to look at the dialog
            dialog->grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/mask-import.png");
        QVERIFY2(dialog->findChild<QLabel*>("maskSummary")->text().contains("leaves most of the field out"),
                 qPrintable(dialog->findChild<QLabel*>("maskSummary")->text()));
        // Black means process: now the rod is tinted and the field shows as it is.
        QRadioButton* dark = dialog->findChildren<QRadioButton*>().at(1);
        QTest::mouseClick(dark, Qt::LeftButton);
        QCOMPARE(dialog->convention(), MaskConvention::DarkProcesses);
        QCOMPARE(dialog->preview().pixel(field), frame.pixel(field));
        QVERIFY(dialog->preview().pixel(onRod) != frame.pixel(onRod));
        QVERIFY(!dialog->findChild<QLabel*>("maskSummary")->text().contains("leaves most"));
        QVERIFY(doc->config().mask.empty());  // nothing changes before OK

        const int steps = doc->undoStack()->count();
        QVERIFY(ok->isEnabled());
        QTest::mouseClick(ok, Qt::LeftButton);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const cv::Mat& mask = doc->config().mask;
        QCOMPARE(cv::countNonZero(mask), g.imageWidth * g.imageHeight - rod.area());
        QCOMPARE(cv::countNonZero(mask(rod)), 0);
        QVERIFY(waitForMask(*window_, mask));
        doc->undoStack()->undo();
        QVERIFY(doc->config().mask.empty());
    }

    void importRefusesAnotherSizeAndOneValue()
    {
        ConfigDocument* doc = window_->document();
        const GeometryOptions& g = doc->config().geometry;
        const QString small = dir_.filePath("small.png"), blank = dir_.filePath("blank.png");
        QVERIFY(cv::imwrite(small.toStdString(), cv::Mat(100, 120, CV_8UC1, cv::Scalar(0))));
        QVERIFY(cv::imwrite(blank.toStdString(), cv::Mat(g.imageHeight, g.imageWidth, CV_8UC1, cv::Scalar(255))));
        MaskImportDialog dialog(doc, window_->lastRun()->result.stages.acquired);
        QPushButton* ok = dialog.buttons()->button(QDialogButtonBox::Ok);
        dialog.setFile(small);
        QVERIFY2(dialog.problem().contains("120x100") && dialog.problem().contains("small.png"), qPrintable(dialog.problem()));
        QVERIFY(!ok->isEnabled());
        dialog.setFile(blank);
        QVERIFY2(dialog.problem().contains("all one value"), qPrintable(dialog.problem()));
        QVERIFY(!ok->isEnabled());
        dialog.setFile(dir_.filePath("missing.png"));
        QVERIFY2(dialog.problem().contains("missing.png"), qPrintable(dialog.problem()));
        QVERIFY(!ok->isEnabled());
        QVERIFY(doc->config().mask.empty());
    }

private:
    MaskEditor* editor() const { return window_->paneEditors()->mask(); }
    ImageView* acquired() const { return window_->pipelineView()->pane(PipelineView::Acquired); }

    QTemporaryDir dir_;
    QString session_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(MaskEditorTest)
#include "app_mask_editor_test.moc"
