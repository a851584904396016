// The workbench window, offscreen, on a copy of the demo session: stepping frames with keys
// changes the panes, a threshold edit re-runs the frame and is undoable, the config saves and
// reloads, a broken config is refused with a dialog naming the key, closing with unsaved
// changes asks first, and at 1366x768 no pane is blank.
#include "ConfigParser.h"
#include "FrameNavigator.h"
#include "MainWindow.h"
#include "PipelineView.h"
#include "ThresholdPanel.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QDirIterator>
#include <QMessageBox>
#include <QtTest>

using namespace omnitune;

namespace {

// Copies the demo session (the repository's copy must never change).
bool copyDemo(const QString& to)
{
    const QString from = QStringLiteral(OMNITUNE_SOURCE_DIR "/sessions/demo");
    QDirIterator it(from, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QString target = to + file.mid(from.size());
        QDir().mkpath(QFileInfo(target).path());
        if (!QFile::copy(file, target)) return false;
    }
    return true;
}

// Answers the next modal message box with `button` and keeps its text. Event driven: checks
// again on every turn of the event loop until the box is there.
void answerNextMessageBox(QMessageBox::StandardButton button, QString* text)
{
    QTimer::singleShot(0, [button, text] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            if (text) *text = box->text();
            box->button(button)->click();
            return;
        }
        answerNextMessageBox(button, text);
    });
}

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

    // Waits until the window shows a run for `frame` with the current config.
    bool waitForFrame(int frame)
    {
        QSignalSpy spy(window_.get(), &MainWindow::runShown);
        for (int i = 0; i < 50; ++i) {
            if (!window_->isProcessing() && window_->lastRun() && window_->lastRun()->frameIndex == frame) return true;
            spy.wait(200);
        }
        return false;
    }

private slots:
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
        window_->document()->undoStack()->setClean();  // no prompt on teardown
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

        window_->document()->undoStack()->undo();
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
        const ConfigLoad reloaded = loadConfig((session_ + "/config.yml").toStdString());
        QVERIFY(reloaded.ok());
        QCOMPARE(reloaded.config.edges.cannyLow, 55);
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
