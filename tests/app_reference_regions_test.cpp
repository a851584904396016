// Issue 12, the automatic camera calibration's reference regions on the panes: in editing mode
// (K) a drag inside the white region moves it and a drag from the black region's corner
// resizes it, on the real acquired pane with QTest mouse events; each drag is one undo step that
// changes only camera_auto.white_* or camera_auto.black_*, and undo puts them back. Another
// pane editor (the mask, M) takes the left button from it; Escape ends the mode.
#include "app/MainWindow.h"
#include "widgets/ConfigDocument.h"
#include "widgets/ImageView.h"
#include "widgets/PaneEditors.h"
#include "widgets/PipelineView.h"
#include "widgets/ReferenceRegionEditor.h"
#include "widgets/ViewTransform.h"
#include "WindowTestSupport.h"

#include <QtTest>

#include <cmath>

using namespace omnitune;
using namespace omnitune::testing;

using Region = ReferenceRegionEditor::Region;

class ReferenceRegionsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        startWindowTests();
        QVERIFY(dir_.isValid());
        QVERIFY(copyDemo(dir_.path()));
    }

    void init()
    {
        QVERIFY(openWindow(window_, dir_.path(), Shown::Active));
        // Both regions on screen, a region's pixel two widget pixels wide.
        const CameraAutoOptions& o = window_->document()->config().cameraAuto;
        window_->pipelineView()->transform()->setZoom(2.0, QPointF(o.whiteX, (o.whiteY + o.blackY) / 2.0));
        QTest::keyClick(window_.get(), Qt::Key_K);
        QVERIFY(editor()->isEditing());
        QCOMPARE(window_->pipelineView()->paneEditor(), editor());
    }

    void cleanup()
    {
        if (window_) window_->document()->discardChanges();
        window_.reset();
    }

    void dragMovesAndResizesOneUndoStepEach()
    {
        ConfigDocument* doc = window_->document();
        const CameraAutoOptions before = doc->config().cameraAuto;
        ImageView* pane = window_->pipelineView()->pane(PipelineView::Acquired);
        const int steps = doc->undoStack()->count();

        // Inside the white region: it moves by the drag, keeping its size.
        const QRect white = editor()->region(Region::White);
        auto [from, to] = dragOnPane(pane, QRectF(white).center(), QRectF(white).center() + QPointF(24, 14));
        const int dx = int(std::lround(to.x() - from.x())), dy = int(std::lround(to.y() - from.y()));
        QVERIFY(dx > 15 && dy > 8);
        const CameraAutoOptions& now = doc->config().cameraAuto;
        QCOMPARE(now.whiteX, before.whiteX + dx);
        QCOMPARE(now.whiteY, before.whiteY + dy);
        QCOMPARE(now.whiteWidth, before.whiteWidth);
        QCOMPARE(now.whiteHeight, before.whiteHeight);
        QCOMPARE(std::get<int>(doc->value("camera_auto.white_x")), before.whiteX + dx);  // the key the config saves
        QCOMPARE(doc->undoStack()->count(), steps + 1);

        // Just outside the black region's lower right corner: it grows from there, its top left stays.
        const QRectF black(editor()->region(Region::Black));
        std::tie(from, to) = dragOnPane(pane, black.bottomRight() + QPointF(1.5, 1.5), black.bottomRight() + QPointF(11.5, 7.5));
        const int gx = int(std::lround(to.x() - from.x())), gy = int(std::lround(to.y() - from.y()));
        QCOMPARE(now.blackX, before.blackX);
        QCOMPARE(now.blackY, before.blackY);
        QCOMPARE(now.blackWidth, before.blackWidth + gx);
        QCOMPARE(now.blackHeight, before.blackHeight + gy);
        QVERIFY(gx > 5 && gy > 2);
        QCOMPARE(now.whiteX, before.whiteX + dx);  // the other region stays
        QCOMPARE(doc->undoStack()->count(), steps + 2);

        if (qEnvironmentVariableIsSet("OMNITUNE_SCREENSHOT_DIR"))  // to look at the regions
            window_->grab().save(qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR") + "/reference-regions.png");

        // A press away from both changes nothing.
        dragOnPane(pane, QPointF(before.blackX - 60, before.blackY), QPointF(before.blackX - 40, before.blackY + 10));
        QCOMPARE(doc->undoStack()->count(), steps + 2);

        doc->undoStack()->undo();
        QCOMPARE(now.blackWidth, before.blackWidth);
        QCOMPARE(now.blackHeight, before.blackHeight);
        doc->undoStack()->undo();
        QCOMPARE(now.whiteX, before.whiteX);
        QCOMPARE(now.whiteY, before.whiteY);
    }

    void aRegionStaysInsideTheFrame()
    {
        ConfigDocument* doc = window_->document();
        const Config& c = doc->config();
        window_->pipelineView()->transform()->fit();
        ImageView* pane = window_->pipelineView()->pane(PipelineView::Acquired);
        const QRectF white(editor()->region(Region::White));
        dragOnPane(pane, white.center(), QPointF(c.geometry.imageWidth + 40, -40));  // beyond the top right corner
        QCOMPARE(c.cameraAuto.whiteY, 0);
        QCOMPARE(c.cameraAuto.whiteX + c.cameraAuto.whiteWidth, c.geometry.imageWidth);
        QCOMPARE(c.cameraAuto.whiteWidth, int(white.width()));
    }

    void oneEditorHoldsTheLeftButton()
    {
        QTest::keyClick(window_.get(), Qt::Key_M);  // the mask editor takes over
        QVERIFY(!editor()->isEditing());
        QVERIFY(window_->pipelineView()->paneEditor() != editor());
        QTest::keyClick(window_.get(), Qt::Key_K);
        QVERIFY(editor()->isEditing());
        QTest::keyClick(window_.get(), Qt::Key_Escape);
        QVERIFY(!editor()->isEditing());
        QCOMPARE(window_->pipelineView()->paneEditor(), nullptr);
    }

private:
    ReferenceRegionEditor* editor() const { return window_->paneEditors()->referenceRegions(); }
    QTemporaryDir dir_;
    std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(ReferenceRegionsTest)
#include "app_reference_regions_test.moc"
