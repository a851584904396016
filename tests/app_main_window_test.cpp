// The workbench window, offscreen, on a copy of the demo session: stepping frames with keys
// changes the panes, a threshold edit re-runs the frame and is undoable, the config saves and
// reloads, a broken config is refused with a dialog naming the key, closing with unsaved
// changes asks first, and at 1366x768 no pane is blank. Issue 13: a second source clears
// every pane before its first frame and shows a frame it cannot process with the reason;
// unsaved edits never cross to another source unasked; the truth drawn is the shown frame's;
// the table's tooltips quote the run's thresholds; the OpenCV path says it has no
// accumulator; the keyboard comes back to the panes after an edit.
#include "widgets/CandidateTableModel.h"
#include "core/ConfigParser.h"
#include "widgets/FrameNavigator.h"
#include "app/MainWindow.h"
#include "widgets/NoticeBar.h"
#include "widgets/PipelineView.h"
#include "widgets/ThresholdPanel.h"
#include "WindowTestSupport.h"

#include "widgets/TruthDocument.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QSpinBox>
#include <QLabel>
#include <QMenu>
#include <QMimeData>
#include <QTableView>
#include <QToolButton>
#include <QtTest>

using namespace omnitune;

namespace {

using namespace omnitune::testing;

bool notBlank(const QImage& image)
{
    if (image.isNull()) return false;
    const QImage grey = image.convertToFormat(QImage::Format_Grayscale8);
    int lo = 255;
    int hi = 0;
    for (int y = 0; y < grey.height(); y += 4)
        for (int x = 0; x < grey.width(); x += 4) {
            lo = std::min<int>(lo, grey.pixelColor(x, y).value());
            hi = std::max<int>(hi, grey.pixelColor(x, y).value());
        }
    return hi - lo > 20;
}

// A key as the user types it: to whatever has the keyboard, shortcuts first.
void typeKey(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QTest::keyClick(QApplication::focusWidget(), key, modifiers);
}

}  // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    QString session_;
    std::unique_ptr<MainWindow> window_;

    bool waitForFrame(int frame) { return omnitune::testing::waitForFrame(*window_, frame); }

private slots:
    void initTestCase()
    {
        startWindowTests();
    }

    void init()
    {
        session_ = freshDemo(tmp_);
        QVERIFY(!session_.isEmpty());
        QVERIFY(openWindow(window_, session_, Shown::AsIs));
    }
    void cleanup()
    {
        if (window_) window_->document()->undoStack()->setClean();  // no prompt on teardown
        window_.reset();
    }

    void opensTheSessionWithItsConfig()
    {
        QCOMPARE(window_->document()->path(), session_ + "/config.yml");
        QCOMPARE(window_->navigator()->frameCount(), 24);
        QVERIFY(window_->lastRun()->result.detection.found);
        QVERIFY(window_->windowTitle().contains("config.yml"));
    }

    void keysStepThroughFrames()
    {
        const QImage first = window_->pipelineView()->pane(PipelineView::Acquired)->image();
        QTest::keyClick(window_.get(), Qt::Key_Right);
        QVERIFY(waitForFrame(1));
        QCOMPARE(window_->navigator()->current(), 1);
        const QImage second = window_->pipelineView()->pane(PipelineView::Acquired)->image();
        QVERIFY(second != first);
        QVERIFY(window_->pipelineView()->pane(PipelineView::Edges)->image() != QImage());
        QTest::keyClick(window_.get(), Qt::Key_End);
        QVERIFY(waitForFrame(23));
        QTest::keyClick(window_.get(), Qt::Key_Right);  // loops round
        QVERIFY(waitForFrame(0));
        QTest::keyClick(window_.get(), Qt::Key_Left);
        QVERIFY(waitForFrame(23));
        QTest::keyClick(window_.get(), Qt::Key_Home);
        QVERIFY(waitForFrame(0));
    }

    void thresholdEditRerunsAndUndoes()
    {
        auto* editor = qobject_cast<QAbstractSpinBox*>(window_->thresholdPanel()->editorFor("validation.min_radius_px"));
        QVERIFY(editor);
        editor->setFocus();
        editor->selectAll();
        QTest::keyClicks(editor, "50");
        QTest::keyClick(editor, Qt::Key_Enter);
        QCOMPARE(window_->document()->config().validation.minRadiusPx, 50.0);
        QCOMPARE(window_->document()->undoStack()->count(), 1);
        QVERIFY(window_->windowTitle().contains("*") || window_->isWindowModified());
        QTRY_VERIFY(!window_->isProcessing() && !window_->lastRun()->result.detection.found);
        for (const auto& c : window_->lastRun()->result.candidates)
            if (c.source == CandidateSource::SpecificHough) QCOMPARE(c.rejected, RejectReason::TooSmall);

        QVERIFY(editor->hasFocus());
        QTest::keyClick(editor, Qt::Key_Z, Qt::ControlModifier);  // the config's undo, though the field has the cursor
        QCOMPARE(window_->document()->config().validation.minRadiusPx, 4.0);
        QTRY_VERIFY(!window_->isProcessing() && window_->lastRun()->result.detection.found);
        QVERIFY(!window_->document()->isDirty());
    }

    void savesAndReloads()
    {
        QVERIFY(!window_->document()->setValue("edges.canny_low", ConfigValue(55)));
        QVERIFY(window_->document()->isDirty());
        QVERIFY(window_->saveConfig());
        QVERIFY(!window_->document()->isDirty());
        QVERIFY(QFile::exists(session_ + "/config.yml.bak"));
        QFile original(QStringLiteral(OMNITUNE_SOURCE_DIR "/sessions/demo/config.yml"));
        QVERIFY(original.open(QIODevice::ReadOnly));
        const QByteArray before = original.readAll();
        QVERIFY(!window_->document()->setValue("edges.canny_low", ConfigValue(50)));
        QVERIFY(window_->saveConfig());  // a second save keeps the first backup: the file as it was
        QFile backup(session_ + "/config.yml.bak");
        QVERIFY(backup.open(QIODevice::ReadOnly));
        QCOMPARE(backup.readAll(), before);
        const ConfigLoad reloaded = loadConfig((session_ + "/config.yml").toStdString());
        QVERIFY(reloaded.ok());
        QCOMPARE(reloaded.config.edges.cannyLow, 50);
    }

    void brokenConfigIsRefusedWithTheKey()
    {
        const QString bad = tmp_.filePath("broken.yml");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("schema: 1\nvalidation:\n  min_non_green_pct: 185\n");
        f.close();
        const double before = window_->document()->config().validation.minNonGreenPct;
        QString text;
        answerNextMessageBox(QMessageBox::Ok, &text);
        QVERIFY(!window_->openConfig(bad));
        QVERIFY2(text.contains("broken.yml") && text.contains("validation.min_non_green_pct"), qPrintable(text));
        QCOMPARE(window_->document()->config().validation.minNonGreenPct, before);
        QCOMPARE(window_->document()->path(), session_ + "/config.yml");
    }

    void loadWarningsStayReadableUntilDismissed()
    {
        QVERIFY(!window_->notices()->isVisible());  // the demo config is complete
        const QString partial = tmp_.filePath("partial.yml");
        QFile f(partial);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("schema: 1\nedges:\n  canny_low: 50\n");
        f.close();
        QVERIFY(window_->openConfig(partial));
        QCOMPARE(window_->document()->config().edges.cannyLow, 50);
        QVERIFY(window_->notices()->isVisible());
        const QString text = window_->notices()->text();
        QVERIFY2(text.contains("partial.yml") && text.contains(": missing, using the default") && text.contains("more"),
                 qPrintable(text));  // dozens of keys missing: the first few and a count
        auto* dismiss = window_->notices()->findChild<QToolButton*>();
        QVERIFY(dismiss);
        QTest::mouseClick(dismiss, Qt::LeftButton);
        QVERIFY(!window_->notices()->isVisible());
    }

    void closingWithUnsavedChangesAsks()
    {
        QVERIFY(!window_->document()->setValue("edges.canny_high", ConfigValue(170)));
        QString text;
        answerNextMessageBox(QMessageBox::Cancel, &text);
        QVERIFY(!window_->close());
        QVERIFY(text.contains("unsaved"));
        QVERIFY(window_->isVisible());
        answerNextMessageBox(QMessageBox::Discard, nullptr);
        QVERIFY(window_->close());
        QVERIFY(window_->document()->isDirty());
        window_.reset();  // destroyed dirty: the undo stack's last signal must not reach the window (ASan)
    }

    void clickingACandidateCentresThePanes()
    {
        window_->pipelineView()->transform()->setZoom(4.0, QPointF(10, 10));
        auto* table = window_->findChild<QTableView*>("candidateTable");
        QVERIFY(table && table->model()->rowCount() > 1);
        const int row = table->model()->rowCount() - 1;
        const BallCandidate& c = window_->candidates()->candidate(row);
        const QRect cell = table->visualRect(table->model()->index(row, CandidateTableModel::ResultColumn));
        QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
        QCOMPARE(window_->pipelineView()->transform()->center(), QPointF(c.x, c.y));
        QCOMPARE(window_->pipelineView()->transform()->zoom(), 4.0);
    }

    void unreadableFrameIsSkippedWithItsFileNamed()
    {
        const QString frame = session_ + "/frames/000001.png";
        QFile f(frame);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("not a png");
        f.close();
        const QImage before = window_->pipelineView()->pane(PipelineView::Acquired)->image();
        QTest::keyClick(window_.get(), Qt::Key_Right);
        QVERIFY(waitForFrame(1));
        QVERIFY(window_->lastRun()->frameUnreadable);
        const QString text = window_->findChild<QLabel*>("result")->text();
        QVERIFY2(text.contains("skipped"), qPrintable(text));
        // Not the previous frame under frame 1's name: no image, and the reason on the pane.
        QVERIFY(window_->pipelineView()->pane(PipelineView::Acquired)->image().isNull());
        QVERIFY(!before.isNull());
        const QString caption = window_->pipelineView()->caption(PipelineView::Acquired);
        QVERIFY2(caption.contains("000001.png"), qPrintable(caption));
        QTest::keyClick(window_.get(), Qt::Key_Right);  // and the next one plays on
        QVERIFY(waitForFrame(2));
        QVERIFY(window_->lastRun()->result.ok());
    }

    void droppedFilesOpenAndAreRemembered()
    {
        const QString config = tmp_.filePath("dropped.yml");
        QFile::remove(config);
        QVERIFY(QFile::copy(session_ + "/config.yml", config));
        QMimeData data;
        data.setUrls({QUrl::fromLocalFile(config)});
        const QPoint at = window_->rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(window_.get(), &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(window_.get(), &drop);
        QTRY_COMPARE(window_->document()->path(), config);

        // Both the session (opened in init) and the dropped config are in File > Open recent.
        QMenu* recent = nullptr;
        for (QMenu* m : window_->findChildren<QMenu*>())
            if (m->title().contains("recent")) recent = m;
        QVERIFY(recent);
        QStringList entries;
        for (QAction* a : recent->actions()) entries << a->text();
        QVERIFY2(entries.size() >= 2 && entries[0].contains("dropped.yml") && entries[1].contains(QFileInfo(session_).fileName()),
                 qPrintable(entries.join(" | ")));

        // Choosing the session entry opens it again, with its own config.
        recent->actions()[1]->trigger();
        QTRY_COMPARE(window_->document()->path(), session_ + "/config.yml");
    }

    // Bug 2 (and 5's notice): the 480x480 image folder after the demo session.
    void secondSourceClearsThePanesAndShowsWhatItCannotProcess()
    {
        const QString images = tmp_.filePath(QStringLiteral("real-%1").arg(QDateTime::currentMSecsSinceEpoch()));
        QVERIFY(QDir().mkpath(images));
        for (int i = 0; i < 3; ++i) {
            const cv::Mat frame = cv::imread((session_ + QStringLiteral("/frames/%1.png").arg(i, 6, 10, QChar('0'))).toStdString());
            QVERIFY(!frame.empty());
            QVERIFY(cv::imwrite(QStringLiteral("%1/img%2.png").arg(images).arg(i).toStdString(), frame(cv::Rect(80, 0, 480, 480))));
        }
        QVERIFY(window_->candidates()->rowCount() > 0);
        const double minRadius = window_->document()->config().validation.minRadiusPx;
        QVERIFY(window_->openSource(images));
        // Before the new source's first frame arrives, nothing of the old one is left.
        PipelineView* view = window_->pipelineView();
        for (int i = 0; i < PipelineView::kPaneCount; ++i) QVERIFY2(view->pane(i)->image().isNull(), qPrintable(view->pane(i)->title()));
        QCOMPARE(window_->candidates()->rowCount(), 0);
        QCOMPARE(view->truth().state, TruthOverlay::Unmarked);
        QVERIFY(!window_->lastRun());
        QVERIFY2(view->caption(PipelineView::Acquired).contains("Opening"), qPrintable(view->caption(PipelineView::Acquired)));

        // The frame does not fit the config: shown all the same, with the reason on it.
        QVERIFY(waitForFrame(0));
        QCOMPARE(view->pane(PipelineView::Acquired)->image().size(), QSize(480, 480));
        QVERIFY(view->pane(PipelineView::Edges)->image().isNull());
        const QString caption = view->caption(PipelineView::Acquired);
        QVERIFY2(caption.contains("not processed") && caption.contains("480x480"), qPrintable(caption));

        // No config.yml there: the session's values go on, unlinked from its file, and it is said.
        QCOMPARE(window_->document()->path(), QString());
        QCOMPARE(window_->document()->config().validation.minRadiusPx, minRadius);
        const QString notice = window_->notices()->text();
        QVERIFY2(notice.contains("carries no config") && notice.contains("not linked"), qPrintable(notice));
    }

    // Bug 5: a session without config.yml after edits to another session's config.
    void unsavedEditsNeverCrossToAnotherSourceUnasked()
    {
        const QString other = tmp_.filePath(QStringLiteral("noconfig-%1").arg(QDateTime::currentMSecsSinceEpoch()));
        QVERIFY(copyDemo(other));
        QVERIFY(QFile::remove(other + "/config.yml"));
        QFile saved(session_ + "/config.yml");
        QVERIFY(saved.open(QIODevice::ReadOnly));
        const QByteArray before = saved.readAll();
        saved.close();
        QVERIFY(!window_->document()->setValue("edges.canny_low", ConfigValue(41)));

        QString question;
        answerNextMessageBox(QMessageBox::Cancel, &question);
        QVERIFY(!window_->openSource(other));  // Cancel: nothing changes
        QVERIFY2(question.contains("unsaved") && question.contains(QFileInfo(other).fileName()), qPrintable(question));
        QVERIFY(window_->document()->isDirty());
        QCOMPARE(window_->document()->path(), session_ + "/config.yml");
        QVERIFY(window_->windowTitle().contains(QFileInfo(session_).fileName()));

        answerNextMessageBox(QMessageBox::Discard, nullptr);
        QVERIFY(window_->openSource(other));
        QVERIFY(!window_->document()->isDirty());
        QCOMPARE(window_->document()->config().edges.cannyLow, 60);  // the edit is gone, as answered
        QCOMPARE(window_->document()->path(), QString());  // Ctrl+S cannot write into the first session
        QVERIFY2(window_->notices()->text().contains("has no config.yml"), qPrintable(window_->notices()->text()));
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QCOMPARE(saved.readAll(), before);
        QVERIFY(waitForFrame(0));
    }

    // Bug 3: frames asked for faster than they are processed, and play.
    void theTruthDrawnIsTheShownFramesOwn()
    {
        const TruthDocument* truth = window_->truth();
        QVERIFY(truth->row(1) && truth->row(6) && truth->row(1)->px != truth->row(6)->px);
        int checked = 0;
        QStringList wrong;
        connect(window_.get(), &MainWindow::runShown, this, [&](int frame) {
            const TruthOverlay drawn = window_->pipelineView()->truth();
            const TruthRow* row = truth->row(frame);
            ++checked;
            if (!row || drawn.state != TruthOverlay::Ball || drawn.x != row->px || drawn.y != row->py)
                wrong << QStringLiteral("frame %1 shown with truth at %2,%3").arg(frame).arg(drawn.x).arg(drawn.y);
            const QString label = window_->findChild<QLabel*>("truth")->text();
            if (row && !label.contains(QStringLiteral("(%1, ").arg(row->px, 0, 'f', 0)))
                wrong << QStringLiteral("frame %1, label %2").arg(frame).arg(label);
        });
        for (int f = 1; f <= 6; ++f) window_->showFrame(f);  // faster than the pipeline
        QVERIFY(waitForFrame(6));
        QTest::keyClick(window_.get(), Qt::Key_Space);  // play
        QTRY_VERIFY(checked >= 8);
        QTest::keyClick(window_.get(), Qt::Key_Space);
        QVERIFY(!window_->navigator()->isPlaying());
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join("\n")));
    }

    // Bug 4: after an edit, the table quotes the threshold the run used.
    void tableTooltipsQuoteTheEditedThreshold()
    {
        QVERIFY(!window_->document()->setValue("validation.min_non_green_pct", ConfigValue(62.5)));
        QTRY_VERIFY(!window_->isProcessing() && window_->lastRun()->config.validation.minNonGreenPct == 62.5);
        const QString tip = window_->candidates()->headerData(CandidateTableModel::NonGreenColumn, Qt::Horizontal, Qt::ToolTipRole).toString();
        QVERIFY2(tip.contains("62.5 %"), qPrintable(tip));
    }

    // Bug 7: cv::HoughCircles has no accumulator; the pane says so and shows its circles.
    void openCvHoughPaneSaysItHasNoAccumulator()
    {
        QVERIFY(window_->pipelineView()->caption(PipelineView::Hough).isEmpty());
        QVERIFY(!window_->document()->setValue("algorithm.method", ConfigValue(std::string("opencv"))));
        QTRY_VERIFY(!window_->isProcessing() && window_->lastRun()->config.algorithm == Algorithm::OpenCv);
        const QString caption = window_->pipelineView()->caption(PipelineView::Hough);
        QVERIFY2(caption.contains("no accumulator"), qPrintable(caption));
        QVERIFY(notBlank(window_->pipelineView()->pane(PipelineView::Hough)->image()));
    }

    // After a threshold edit, Escape or a click on a pane gives arrows and Space back to the
    // frames; transport controls never keep the keyboard.
    void keyboardComesBackToTheFramesAfterAnEdit()
    {
        window_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(window_.get()));
        auto* editor = qobject_cast<QAbstractSpinBox*>(window_->thresholdPanel()->editorFor("validation.min_radius_px"));
        QVERIFY(editor);
        QTest::mouseClick(editor, Qt::LeftButton);
        editor->selectAll();
        QTest::keyClicks(editor, "5");
        QTest::keyClick(editor, Qt::Key_Enter);
        QCOMPARE(window_->document()->config().validation.minRadiusPx, 5.0);
        QCOMPARE(QApplication::focusWidget(), editor);
        typeKey(Qt::Key_Escape);
        QVERIFY(QApplication::focusWidget() != editor);
        typeKey(Qt::Key_Right);
        QVERIFY(waitForFrame(1));
        QCOMPARE(window_->document()->config().validation.minRadiusPx, 5.0);  // the arrow did not step the field

        QTest::mouseClick(editor, Qt::LeftButton);
        QCOMPARE(QApplication::focusWidget(), editor);
        ImageView* pane = window_->pipelineView()->pane(PipelineView::Segmented);
        QTest::mouseClick(pane, Qt::LeftButton, Qt::NoModifier, pane->rect().center());
        typeKey(Qt::Key_Right);
        QVERIFY(waitForFrame(2));

        // The frame box is a text field too: after a jump, Escape gives Space back to playing.
        auto* frameBox = window_->navigator()->findChild<QSpinBox*>();
        QTest::mouseClick(frameBox, Qt::LeftButton);
        frameBox->selectAll();
        QTest::keyClicks(frameBox, "4");
        QTest::keyClick(frameBox, Qt::Key_Enter);
        QVERIFY(waitForFrame(4));
        typeKey(Qt::Key_Escape);
        typeKey(Qt::Key_Space);
        QVERIFY(window_->navigator()->isPlaying());
        typeKey(Qt::Key_Space);
        QVERIFY(!window_->navigator()->isPlaying());

        // Every transport control: clicked, it leaves the keyboard where it was (a shortcut
        // beats a button's own Space, but not a text field's, so none may take the keyboard).
        for (QWidget* w : window_->navigator()->findChildren<QWidget*>()) {
            if (!qobject_cast<QToolButton*>(w) && !qobject_cast<QCheckBox*>(w) && !qobject_cast<QComboBox*>(w)
                && !qobject_cast<QSlider*>(w))
                continue;
            QCOMPARE(w->focusPolicy(), Qt::NoFocus);
        }
        auto* loop = window_->navigator()->findChild<QCheckBox*>();
        QTest::mouseClick(loop, Qt::LeftButton);
        QVERIFY(!loop->isChecked());
        QTest::mouseClick(loop, Qt::LeftButton);
        typeKey(Qt::Key_Space);
        QVERIFY(window_->navigator()->isPlaying());  // Space played rather than ticking "loop"
        QVERIFY(loop->isChecked());
        typeKey(Qt::Key_Space);
        QVERIFY(!window_->navigator()->isPlaying());
    }

    void noPaneIsBlankOnALaptopScreen()
    {
        window_->resize(1366, 768);
        QTRY_VERIFY(!window_->isProcessing());
        const QImage shot = window_->grab().toImage();
        QCOMPARE(shot.size(), QSize(1366, 768));
        for (int i = 0; i < PipelineView::kPaneCount; ++i) {
            ImageView* pane = window_->pipelineView()->pane(i);
            QVERIFY2(pane->isVisible() && pane->width() > 150 && pane->height() > 110, qPrintable(pane->title()));
            const QRect r(pane->mapTo(window_.get(), QPoint(0, 0)), pane->size());
            QVERIFY2(notBlank(shot.copy(r)), qPrintable(pane->title()));
        }
        shot.save(tmp_.filePath("window.png"));
    }
};

QTEST_MAIN(MainWindowTest)
#include "app_main_window_test.moc"
