// The Colours panel in the workbench window, offscreen, on a copy of the demo session (issue
// 10): brushing over the ball on the panes adds exactly its colours to the selected class and
// the segmented pane shows that class there; Ctrl+brush takes them out again; undo restores
// each step; a hue box made to wrap through 0 with the spin boxes classifies red; a slider drag
// updates the segmented pane live, is one undo step and saves nothing; masked pixels are no
// samples and the status line says so; the wand takes the ball from one click; "show only this
// class" and the overlap stripes change the segmented pane.
#include "app/MainWindow.h"
#include "calib/colour/SampleArea.h"
#include "core/ColorLut.h"
#include "widgets/ColourBoxEditor.h"
#include "widgets/ColourEditor.h"
#include "widgets/ColourPlaneView.h"
#include "widgets/ColourSampler.h"
#include "widgets/GeometryEditor.h"
#include "widgets/MaskEditor.h"
#include "widgets/PaneEditors.h"
#include "widgets/RadialSensorEditor.h"
#include "widgets/ConfigDocument.h"
#include "widgets/PipelineView.h"
#include "widgets/TruthDocument.h"
#include "FileBytes.h"
#include "WindowTestSupport.h"

#include <QAction>
#include <QCheckBox>
#include <QDockWidget>
#include <QLabel>
#include <QListWidget>
#include <QScrollArea>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

class ColourEditorTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    QString session_;
    std::unique_ptr<MainWindow> window_;
    QPointF ball_;      // the ball's centre on frame 0 (truth.csv)
    double radius_ = 0;

    ColourEditor* editor() const { return window_->colourEditor(); }
    ImageView* pane(int i) const { return window_->pipelineView()->pane(i); }
    QPoint widgetPos(QPointF image) const { return pane(PipelineView::Acquired)->toWidget(image).toPoint(); }
    const cv::Mat& classes() const { return window_->lastRun()->result.classes; }

    void open()
    {
        session_ = freshDemo(tmp_);
        QVERIFY(!session_.isEmpty());
        // The Colours tab in front, as when calibrating colours.
        QVERIFY(openWindow(window_, session_, Shown::AsIs, [](MainWindow& w) { w.findChild<QDockWidget*>("colours")->raise(); }));
        const TruthRow* t = window_->truth()->row(0);
        QVERIFY(t && t->ballVisible);
        ball_ = QPointF(t->px, t->py);
        radius_ = t->radiusPx;
        // Zoomed on the ball, so that a mouse step is less than an image pixel.
        window_->pipelineView()->transform()->setZoom(8.0, ball_);
    }

    // Waits until the panes show a run of the document's current colours.
    bool waitForColours()
    {
        QSignalSpy spy(window_.get(), &MainWindow::runShown);
        for (int i = 0; i < 50; ++i) {
            const auto run = window_->lastRun();
            if (!window_->isProcessing() && run && run->config.colors.classes == window_->document()->config().colors.classes)
                return true;
            spy.wait(200);
        }
        return false;
    }

    // A stroke with real mouse events on the acquired pane through the image points `path`.
    void stroke(const std::vector<QPointF>& path, Qt::KeyboardModifiers modifiers)
    {
        QWidget* w = pane(PipelineView::Acquired);
        QTest::mousePress(w, Qt::LeftButton, modifiers, widgetPos(path.front()));
        for (std::size_t i = 1; i < path.size(); ++i) {
            const QPoint p = widgetPos(path[i]);
            QMouseEvent move(QEvent::MouseMove, p, w->mapToGlobal(p), Qt::NoButton, Qt::LeftButton, modifiers);
            QApplication::sendEvent(w, &move);
        }
        QTest::mouseRelease(w, Qt::LeftButton, modifiers, widgetPos(path.back()));
    }

    // Share of `pixels` whose class id is `id` on the run on screen.
    double shareOf(const std::vector<cv::Point>& pixels, int id) const
    {
        int n = 0;
        for (const cv::Point& p : pixels) n += classes().at<std::uint8_t>(p) == id ? 1 : 0;
        return pixels.empty() ? 0.0 : double(n) / double(pixels.size());
    }

    // The ball's pixels well inside its rim, and a ring of carpet around it.
    std::vector<cv::Point> ballInside() const
    {
        return discPixels(cv::Point(int(std::lround(ball_.x())), int(std::lround(ball_.y()))), int(radius_) - 2,
                          classes().size());
    }
    std::vector<cv::Point> carpetAround() const
    {
        std::vector<cv::Point> out;
        for (const cv::Point& p : discPixels(cv::Point(int(ball_.x()), int(ball_.y())), int(radius_) + 10, classes().size()))
            if (std::hypot(p.x - ball_.x(), p.y - ball_.y()) > radius_ + 4) out.push_back(p);
        return out;
    }

    int findClass(const std::string& name) const
    {
        return findColourClass(window_->document()->config().colors.classes, name);
    }

private slots:
    void initTestCase()
    {
        startWindowTests();
    }
    void cleanup() { window_.reset(); }

    void brushAddsTheBallRemoveTakesItOutUndoRestores()
    {
        open();
        ConfigDocument* doc = window_->document();
        // Compared as the segmented pane's colours: a class put first shifts every class id.
        const QImage segmentedBefore = pane(PipelineView::Segmented)->image();

        // A new class at the top of the list, so that it wins the ball's pixels.
        QVERIFY(!editor()->addClass());
        while (editor()->currentClass() > 0) QVERIFY(!editor()->moveClass(-1));
        QVERIFY(!editor()->renameClass("my_ball"));
        QVERIFY(!editor()->setRole(ColourRole::Ball));
        const int id = 1;  // list position 0
        const auto display = doc->config().colors.classes[0].display;
        QVERIFY(waitForColours());
        QCOMPARE(shareOf(ballInside(), id), 0.0);  // its box is off: nothing yet
        const int stepsBefore = doc->undoStack()->count();

        // C turns sampling on (the Colours menu's action); a brush stroke across the ball's middle.
        QAction* sample = window_->findChild<QAction*>("sampleColours");
        QVERIFY(sample);
        sample->trigger();
        QVERIFY(window_->pipelineView()->isSampling());
        editor()->sampler()->setBrushRadius(int(radius_) - 3);
        const std::vector<QPointF> path = {ball_ - QPointF(1, 0), ball_, ball_ + QPointF(1, 0)};
        stroke(path, Qt::NoModifier);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 1);  // one stroke, one undo step
        QVERIFY2(window_->statusBar()->currentMessage().contains("added"), qPrintable(window_->statusBar()->currentMessage()));
        QVERIFY(waitForColours());
        // The brushed pixels are the new class (a few at the LUT's bin borders may not be), the
        // carpet around the ball is untouched, and so is every pixel away from the ball.
        std::vector<cv::Point> brushed;
        for (const QPointF& p : path) brushed.emplace_back(int(std::floor(p.x())), int(std::floor(p.y())));
        brushed = strokePixels(brushed, int(radius_) - 3, classes().size());
        const double inBrush = shareOf(brushed, id);
        QVERIFY2(inBrush > 0.95, qPrintable(QString::number(inBrush)));
        QCOMPARE(shareOf(carpetAround(), id), 0.0);
        const QImage after = pane(PipelineView::Segmented)->image();
        int changedAway = 0;
        for (int y = 0; y < after.height(); ++y)
            for (int x = 0; x < after.width(); ++x)
                if (std::hypot(x - ball_.x(), y - ball_.y()) > radius_ + 2 && after.pixel(x, y) != segmentedBefore.pixel(x, y))
                    ++changedAway;
        QCOMPARE(changedAway, 0);
        const QPoint c(int(std::lround(ball_.x())), int(std::lround(ball_.y())));
        QCOMPARE(pane(PipelineView::Segmented)->image().pixelColor(c), QColor(display[2], display[1], display[0]));
        QVERIFY(pane(PipelineView::Segmented)->image() != segmentedBefore);

        // Ctrl: the same stroke takes the colours out again.
        stroke(path, Qt::ControlModifier);
        QCOMPARE(doc->undoStack()->count(), stepsBefore + 2);
        QVERIFY(waitForColours());
        QCOMPARE(shareOf(ballInside(), id), 0.0);
        QCOMPARE(pane(PipelineView::Segmented)->image(), segmentedBefore);  // as before the class got anything

        // Undo: the colours are back; undo again: gone.
        doc->undoStack()->undo();
        QVERIFY(waitForColours());
        QVERIFY(shareOf(brushed, id) > 0.95);
        doc->undoStack()->undo();
        QVERIFY(waitForColours());
        QCOMPARE(shareOf(ballInside(), id), 0.0);
        QCOMPARE(pane(PipelineView::Segmented)->image(), segmentedBefore);
    }

    void strokesOnSeveralFramesAddUp()
    {
        open();
        ConfigDocument* doc = window_->document();
        QVERIFY(!editor()->addClass());
        editor()->sampler()->setSampling(true);
        editor()->sampler()->setBrushRadius(1);
        stroke({ball_}, Qt::NoModifier);
        const HsvRange first = doc->config().colors.classes.back().boxes[0];
        QVERIFY(first.enabled);
        window_->showFrame(3);
        QVERIFY(waitForFrame(*window_, 3));
        const TruthRow* t = window_->truth()->row(3);
        QVERIFY(t);
        window_->pipelineView()->transform()->setZoom(8.0, QPointF(t->px, t->py));
        ball_ = QPointF(t->px, t->py);
        stroke({ball_}, Qt::NoModifier);
        const HsvRange both = doc->config().colors.classes.back().boxes[0];
        // The second frame's ball grew the box; what the first gave is still in it.
        QVERIFY(both.sMin <= first.sMin && both.sMax >= first.sMax && both.vMin <= first.vMin && both.vMax >= first.vMax);
        QVERIFY(both != first);
    }

    void maskedPixelsAreNoSamples()
    {
        open();
        ConfigDocument* doc = window_->document();
        QVERIFY(!editor()->addClass());
        editor()->sampler()->setSampling(true);
        const int steps = doc->undoStack()->count();
        // The robot centre is inside the inner radius: never processed.
        const GeometryOptions& g = doc->config().geometry;
        window_->pipelineView()->transform()->setZoom(2.0, QPointF(g.centerX, g.centerY));
        stroke({QPointF(g.centerX, g.centerY)}, Qt::NoModifier);
        QCOMPARE(doc->undoStack()->count(), steps);
        QVERIFY2(window_->statusBar()->currentMessage().contains("masked"), qPrintable(window_->statusBar()->currentMessage()));
        QVERIFY(!doc->config().colors.classes.back().boxes[0].enabled);
    }

    // Sampling and the mask / sensor editors share the panes' left button: one at a time.
    void samplingAndPaneEditorsExcludeEachOther()
    {
        open();
        MaskEditor* mask = window_->paneEditors()->mask();
        editor()->sampler()->setSampling(true);
        mask->setEditing(true);
        QVERIFY(mask->isEditing());
        QVERIFY(!editor()->sampler()->isSampling());
        editor()->sampler()->setSampling(true);
        QVERIFY(!mask->isEditing());
        window_->paneEditors()->sensors()->setEditing(true);
        QVERIFY(!editor()->sampler()->isSampling());
        // The geometry editor takes part in the same hand-over.
        GeometryEditor* geometry = window_->geometryEditor();
        geometry->setEditing(true);
        QVERIFY(!window_->paneEditors()->sensors()->isEditing());
        editor()->sampler()->setSampling(true);
        QVERIFY(!geometry->isEditing());
        geometry->setEditing(true);
        QVERIFY(!editor()->sampler()->isSampling());
    }

    void wandTakesTheBallFromOneClick()
    {
        open();
        ConfigDocument* doc = window_->document();
        QVERIFY(!editor()->addClass());
        while (editor()->currentClass() > 0) QVERIFY(!editor()->moveClass(-1));
        editor()->sampler()->setSampling(true);
        QAction* wand = window_->findChild<QAction*>("magicWand");
        QVERIFY(wand);
        wand->trigger();
        QCOMPARE(editor()->sampler()->tool(), ColourSampler::Tool::Wand);
        stroke({ball_}, Qt::NoModifier);
        QVERIFY(doc->config().colors.classes[0].boxes[0].enabled);
        QVERIFY(waitForColours());
        const double inBall = shareOf(ballInside(), 1);
        QVERIFY2(inBall > 0.9, qPrintable(QString::number(inBall)));
        QCOMPARE(shareOf(carpetAround(), 1), 0.0);
    }

    void wrappedRedHueClassifiesRed()
    {
        open();
        ConfigDocument* doc = window_->document();
        QVERIFY(!editor()->addClass());
        while (editor()->currentClass() > 0) QVERIFY(!editor()->moveClass(-1));
        ColourBoxEditor* box = editor()->boxEditor();
        box->enabledBox()->setChecked(true);
        box->spinBox(ColourBoxEditor::HMin)->setValue(170);
        box->spinBox(ColourBoxEditor::HMax)->setValue(10);
        box->spinBox(ColourBoxEditor::SMin)->setValue(100);
        box->spinBox(ColourBoxEditor::VMin)->setValue(80);
        const HsvRange r = doc->config().colors.classes[0].boxes[0];
        QCOMPARE(r.hMin, 170);
        QCOMPARE(r.hMax, 10);
        QVERIFY(r.enabled);
        const ColorLut lut(doc->config().colors);
        const auto red = ColorClass(1);
        QCOMPARE(lut.classifyBgr(20, 20, 220), red);   // hue 0
        QCOMPARE(lut.classifyBgr(90, 30, 220), red);   // hue ~170: below 0 on the circle
        QCOMPARE(lut.classifyBgr(20, 60, 220), red);   // hue ~6
        QVERIFY(lut.classifyBgr(20, 200, 220) != red); // yellow, hue ~30
        QVERIFY(lut.classifyBgr(220, 20, 20) != red);  // blue, hue 120
        QVERIFY(!editor()->findChild<QLabel*>("wrapNote")->isHidden());
    }

    void sliderDragIsLiveOneUndoStepAndSavesNothing()
    {
        open();
        ConfigDocument* doc = window_->document();
        const std::string saved = filetest::readFile((session_ + "/config.yml").toStdString());
        const int green = findClass("green");
        QVERIFY(green >= 0);
        editor()->selectClass(green);
        const HsvRange was = doc->config().colors.classes[std::size_t(green)].boxes[0];
        const QImage before = pane(PipelineView::Segmented)->image();
        const int steps = doc->undoStack()->count();

        QSlider* s = editor()->boxEditor()->slider(ColourBoxEditor::SMin);
        s->setSliderDown(true);
        s->setValue(was.sMin + 60);
        s->setValue(was.sMin + 120);  // a narrower green: pale carpet becomes no class
        QCOMPARE(doc->config().colors.classes[std::size_t(green)].boxes[0].sMin, was.sMin + 120);  // live
        QCOMPARE(doc->undoStack()->count(), steps);  // no step while dragging
        QVERIFY(waitForColours());
        QVERIFY(pane(PipelineView::Segmented)->image() != before);  // the pane followed the slider
        s->setSliderDown(false);  // release
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->config().colors.classes[std::size_t(green)].boxes[0].sMin, was.sMin + 120);
        QVERIFY(doc->isDirty());
        QVERIFY(filetest::readFile((session_ + "/config.yml").toStdString()) == saved);  // nothing saved
        doc->undoStack()->undo();
        QCOMPARE(doc->config().colors.classes[std::size_t(green)].boxes[0].sMin, was.sMin);
        QCOMPARE(s->value(), was.sMin);  // the slider follows the undo
    }

    void planeDragMovesABoundInOneStep()
    {
        open();
        ConfigDocument* doc = window_->document();
        const int green = findClass("green");
        editor()->selectClass(green);
        const HsvRange was = doc->config().colors.classes[std::size_t(green)].boxes[0];
        ColourPlaneView* plane = editor()->planeView();
        plane->resize(360, 400);
        const int steps = doc->undoStack()->count();
        // Grab the box's H max edge at mid saturation and drag it 10 hue steps lower.
        const int midS = (was.sMin + was.sMax) / 2;
        const QPointF edge = plane->planePoint(was.hMax, midS) + QPointF(plane->width() / 360.0, 0);
        const QPointF to = plane->planePoint(was.hMax - 10, midS);
        QTest::mousePress(plane, Qt::LeftButton, {}, edge.toPoint());
        QMouseEvent move(QEvent::MouseMove, to, plane->mapToGlobal(to.toPoint()), Qt::NoButton, Qt::LeftButton, {});
        QApplication::sendEvent(plane, &move);
        QCOMPARE(doc->undoStack()->count(), steps);  // live, no step yet
        QVERIFY(std::abs(doc->config().colors.classes[std::size_t(green)].boxes[0].hMax - (was.hMax - 10)) <= 1);
        QTest::mouseRelease(plane, Qt::LeftButton, {}, to.toPoint());
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const HsvRange now = doc->config().colors.classes[std::size_t(green)].boxes[0];
        QVERIFY(std::abs(now.hMax - (was.hMax - 10)) <= 1);
        QCOMPARE(now.hMin, was.hMin);
        QCOMPARE(now.sMin, was.sMin);
        QCOMPARE(editor()->boxEditor()->spinBox(ColourBoxEditor::HMax)->value(), now.hMax);
        doc->undoStack()->undo();
        QCOMPARE(doc->config().colors.classes[std::size_t(green)].boxes[0].hMax, was.hMax);
    }

    // With OMNITUNE_SCREENSHOT_DIR set: the window with the Colours tab after sampling a ball
    // (docs/images/colours.png comes from here, under xvfb-run for real fonts).
    void screenshot()
    {
        const QString dir = qEnvironmentVariable("OMNITUNE_SCREENSHOT_DIR");
        if (dir.isEmpty()) QSKIP("OMNITUNE_SCREENSHOT_DIR not set");
        open();
        window_->resize(1366, 768);
        QVERIFY(!editor()->addClass());
        while (editor()->currentClass() > 0) QVERIFY(!editor()->moveClass(-1));
        QVERIFY(!editor()->renameClass("my_ball"));
        QVERIFY(!editor()->setRole(ColourRole::Ball));
        editor()->sampler()->setSampling(true);
        stroke({ball_ - QPointF(2, 0), ball_ + QPointF(2, 0)}, Qt::NoModifier);
        editor()->setFlagOverlaps(true);
        window_->pipelineView()->transform()->setZoom(3.0, ball_);
        QVERIFY(waitForColours());
        // The shares' new lines laid out first (grabbed at once, the picture had them cut).
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QVERIFY(editor()->sharesLabel()->height() >= editor()->sharesLabel()->sizeHint().height());
        QVERIFY(window_->grab().save(dir + "/colours.png"));
        auto* scroll = editor()->findChild<QScrollArea*>("colourScroll");
        QVERIFY(scroll);
        QVERIFY(scroll->widget()->grab().save(dir + "/colours-tab.png"));  // the whole tab, scrolled or not
    }

    void classViewsAndShares()
    {
        open();
        ConfigDocument* doc = window_->document();
        const int green = findClass("green");
        editor()->selectClass(green);
        QVERIFY(waitForColours());
        const ClassShares& shares = editor()->shares();
        QVERIFY(shares.processed > 0);
        QVERIFY(shares.pct(shares.counts[std::size_t(green)]) > 50.0);  // the demo is mostly carpet
        QVERIFY(editor()->classList()->item(green)->text().contains("%"));

        // Only green: the ball's pixels are dimmed, the carpet's are as before.
        const QImage all = pane(PipelineView::Segmented)->image();
        editor()->setOnlyThisClass(true);
        const QImage only = pane(PipelineView::Segmented)->image();
        const QPoint c(int(std::lround(ball_.x())), int(std::lround(ball_.y())));
        QVERIFY(only.pixelColor(c).value() < all.pixelColor(c).value());
        const QPoint carpet(int(ball_.x()) + int(radius_) + 8, int(ball_.y()));
        QCOMPARE(only.pixelColor(carpet), all.pixelColor(carpet));
        editor()->setOnlyThisClass(false);
        QCOMPARE(pane(PipelineView::Segmented)->image(), all);

        // A second class over the carpet's colours: its pixels are claimed twice and striped.
        QVERIFY(!editor()->addClass());
        editor()->sampler()->setSampling(true);
        stroke({QPointF(carpet)}, Qt::NoModifier);
        QVERIFY(waitForColours());
        QVERIFY(editor()->shares().overlapCount > 0);
        editor()->setFlagOverlaps(true);
        const QColor flagged = pane(PipelineView::Segmented)->image().pixelColor(carpet);
        QVERIFY2(flagged == QColor(255, 255, 255) || flagged == QColor(255, 0, 0), qPrintable(flagged.name()));
        QVERIFY(editor()->sharesLabel()->text().contains("two or more"));
        Q_UNUSED(doc);
    }
};

QTEST_MAIN(ColourEditorTest)
#include "app_colour_editor_test.moc"
