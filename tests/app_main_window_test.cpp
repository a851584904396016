// The workbench window, offscreen, on a copy of the demo session: stepping frames with keys
// changes the panes, a threshold edit re-runs the frame and is undoable, the config saves and
// reloads, a broken config is refused with a dialog naming the key, closing with unsaved
// changes asks first, and at 1366x768 no pane is blank.
#include "widgets/CandidateTableModel.h"
#include "core/ConfigParser.h"
#include "widgets/FrameNavigator.h"
#include "app/MainWindow.h"
#include "widgets/NoticeBar.h"
#include "widgets/PipelineView.h"
#include "widgets/ThresholdPanel.h"
#include "WindowTestSupport.h"

#include <QAbstractSpinBox>
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
        QStandardPaths::setTestModeEnabled(true);  // recent files: not the user's settings
        QSettings().clear();
    }

    void init()
    {
        session_ = tmp_.filePath(QStringLiteral("demo-%1").arg(QDateTime::currentMSecsSinceEpoch()));
        QVERIFY(copyDemo(session_));
        window_ = std::make_unique<MainWindow>();
        window_->show();
        QVERIFY(window_->openSource(session_));
        QVERIFY(waitForFrame(0));
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
        QVERIFY2(text.contains("skipped") && text.contains("000001.png"), qPrintable(text));
        QCOMPARE(window_->pipelineView()->pane(PipelineView::Acquired)->image(), before);  // the last good frame stays
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
