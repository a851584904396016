// "Apply to whole session" (issue 5), offscreen, on copies of the demo session: the sweep
// counts every frame and agrees with the batch evaluation, reports false positives only with
// truth, stops early when cancelled, refuses a config that cannot run; in the window, a
// stricter threshold makes detections vanish and the slider marks exactly those frames,
// later edits flag the marks outdated, and the action needs a source.
#include "calib/eval/BatchRun.h"
#include "core/ConfigParser.h"
#include "widgets/FrameNavigator.h"
#include "app/MainWindow.h"
#include "widgets/MarkedSlider.h"
#include "calib/session/SessionReader.h"
#include "calib/source/SessionSource.h"
#include "widgets/SessionSweepPanel.h"
#include "WindowTestSupport.h"

#include <QAction>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QToolTip>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

constexpr int kDemoFrames = 24;

std::map<int, TruthRow> truthOf(const QString& session)
{
    const SessionOpen opened = SessionReader::open(session.toStdString());
    return opened.ok() ? opened.reader->truth() : std::map<int, TruthRow>{};
}

Config configOf(const QString& session)
{
    const ConfigLoad load = loadConfig((session + "/config.yml").toStdString());
    return load.config;
}

// What omnitune-eval computes for the session: the numbers the sweep must reproduce.
EvaluationRow batchEvaluation(const QString& session, const Config& config)
{
    SessionOpen opened = SessionReader::open(session.toStdString());
    SessionSource source(*opened.reader);
    Pipeline pipeline(config);
    std::vector<FrameOutcome> outcomes;
    runBatch(source, pipeline, [&](int i, const Frame*, const PipelineResult& r) {
        outcomes.push_back(outcomeOf(i, r));
    });
    return evaluate(outcomes, opened.reader->truth());
}

// Receives the result the way the GUI does: queued to an object of the test's thread.
std::shared_ptr<const SweepResult> runToEnd(SessionSweep& sweep)
{
    std::shared_ptr<const SweepResult> result;
    QObject receiver;
    QObject::connect(&sweep, &SessionSweep::finished, &receiver,
                     [&result](std::shared_ptr<const SweepResult> r) { result = std::move(r); });
    sweep.start();
    return QTest::qWaitFor([&result] { return result != nullptr; }, 60000) ? result : nullptr;
}

}  // namespace

class SessionSweepTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    int sessions_ = 0;

    QString freshSession()
    {
        const QString dir = tmp_.filePath(QStringLiteral("demo-%1").arg(sessions_++));
        return copyDemo(dir) ? dir : QString();
    }

    // Runs Session > Apply to whole session in `window` and waits for its result.
    static std::shared_ptr<const SweepResult> applyInWindow(MainWindow& window)
    {
        auto* action = window.findChild<QAction*>("applyToSession");
        if (!action || !action->isEnabled()) return nullptr;
        action->trigger();
        auto* dialog = window.findChild<SessionSweepPanel*>();
        if (!dialog) return nullptr;
        QSignalSpy finished(dialog, &SessionSweepPanel::sweepFinished);
        if (!finished.wait(60000)) return nullptr;
        return finished.at(0).at(0).value<std::shared_ptr<const SweepResult>>();
    }

private slots:
    void initTestCase()
    {
        startWindowTests();
    }

    void sweepMatchesTheBatchEvaluation()
    {
        const QString session = freshSession();
        QVERIFY(!session.isEmpty());
        SweepRequest request;
        request.sourcePath = session;
        request.current = configOf(session);
        request.savedConfigPath = session + "/config.yml";
        request.truth = truthOf(session);
        QVERIFY(!request.truth.empty());
        SessionSweep sweep(request);
        QVector<QPair<int, int>> progress;
        connect(&sweep, &SessionSweep::progress, this, [&progress](int done, int total) { progress.push_back({done, total}); });
        const auto r = runToEnd(sweep);
        QVERIFY(r);
        QVERIFY2(r->ok(), r->error.c_str());
        QCOMPARE(r->total, kDemoFrames);
        QCOMPARE(r->visited, kDemoFrames);
        QVERIFY(!r->cancelled);
        QCOMPARE(int(r->current.size()), kDemoFrames);
        QTRY_COMPARE(progress.size(), kDemoFrames + 1);  // 0, then after each frame
        QCOMPARE(progress.first(), qMakePair(0, kDemoFrames));
        QCOMPARE(progress.last(), qMakePair(kDemoFrames, kDemoFrames));

        const EvaluationRow expected = batchEvaluation(session, request.current);
        QCOMPARE(r->currentRow.frames, kDemoFrames);
        QCOMPARE(r->currentRow.withBall, expected.withBall);
        QCOMPARE(r->currentRow.correct, expected.correct);
        QCOMPARE(r->currentRow.detectionRatioPct, expected.detectionRatioPct);
        QCOMPARE(r->currentRow.falsePositives, expected.falsePositives);
        QVERIFY(r->currentRow.detectionRatioPct >= 90.0);
        QVERIFY(r->currentRow.timeAvgMs > 0 && r->currentRow.timeMinMs <= r->currentRow.timeMaxMs);

        // The saved file holds the same config: it ran once and nothing changed.
        QVERIFY(r->hasSaved && r->savedIsCurrent);
        QCOMPARE(int(r->comparison.frames.size()), kDemoFrames);
        QCOMPARE(r->comparison.changed(), 0);
        QCOMPARE(sweepMarks(*r).size(), expected.correct + expected.falsePositives);  // Detected only
    }

    void cancelStopsEarlyWithAPartialResult()
    {
        const QString session = freshSession();
        SweepRequest request;
        request.sourcePath = session;
        request.current = configOf(session);
        request.current.validation.minCircularityPct = 90;  // differs from the file: both configs run
        request.savedConfigPath = session + "/config.yml";
        request.truth = truthOf(session);
        SessionSweep sweep(request);
        // Direct: cancel() is thread-safe, and the sweep stops before the next frame.
        connect(&sweep, &SessionSweep::progress, &sweep, [&sweep](int done, int) {
            if (done == 5) sweep.cancel();
        }, Qt::DirectConnection);
        const auto r = runToEnd(sweep);
        QVERIFY(r);
        QVERIFY(r->ok());
        QVERIFY(r->cancelled);
        QCOMPARE(r->visited, 5);
        QCOMPARE(int(r->current.size()), 5);
        QCOMPARE(int(r->saved.size()), 5);
        QVERIFY(r->hasSaved && !r->savedIsCurrent);
        QCOMPARE(r->currentRow.frames, 5);
        QCOMPARE(int(r->comparison.frames.size()), 5);
    }

    void aConfigThatCannotRunIsAMessage()
    {
        const QString session = freshSession();
        SweepRequest request;
        request.sourcePath = session;
        request.current = configOf(session);
        request.current.edges.cannyLow = 200;  // above canny_high: checkConfig refuses it
        request.current.edges.cannyHigh = 100;
        SessionSweep sweep(request);
        const auto r = runToEnd(sweep);
        QVERIFY(r);
        QVERIFY(!r->ok());
        QVERIFY2(QString::fromStdString(r->error).contains("cannot run") && QString::fromStdString(r->error).contains("canny"), r->error.c_str());

        SweepRequest missing;
        missing.sourcePath = tmp_.filePath("no-such-session");
        missing.current = configOf(session);
        SessionSweep sweep2(missing);
        const auto r2 = runToEnd(sweep2);
        QVERIFY(r2 && !r2->ok());
        QVERIFY2(QString::fromStdString(r2->error).contains("no-such-session"), r2->error.c_str());
    }

    void actionNeedsASource()
    {
        MainWindow window;
        auto* action = window.findChild<QAction*>("applyToSession");
        QVERIFY(action);
        QVERIFY(!action->isEnabled());
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL + Qt::Key_R));
        QVERIFY(window.openSource(freshSession()));
        QVERIFY(action->isEnabled());
        window.document()->undoStack()->setClean();
    }

    void stricterThresholdMarksVanishedFrames()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openSource(freshSession()));
        QVERIFY(waitForFrame(window, 0));
        MarkedSlider* slider = window.navigator()->slider();
        // The live pipeline marks the frame it showed with a ball.
        QVERIFY(window.lastRun()->result.detection.found);
        QVERIFY(slider->hasMark(0, FrameMarkKind::Detected));

        QVERIFY(!window.document()->setValue("validation.min_circularity_pct", ConfigValue(100.0)));
        QVERIFY(!window.document()->setValue("validation.circle_fit", ConfigValue(false)));  // thesis' band
        const auto r = applyInWindow(window);
        QVERIFY(r);
        QVERIFY2(r->ok(), r->error.c_str());
        QVERIFY(r->hasSaved && !r->savedIsCurrent);
        QVERIFY(r->comparison.vanished > 0);
        QCOMPARE(r->comparison.appeared, 0);
        QVERIFY(r->currentRow.correct < r->savedRow.correct);
        for (const FrameComparison& c : r->comparison.frames) {
            QCOMPARE(slider->hasMark(c.frame, FrameMarkKind::Vanished), c.change == FrameChange::Vanished);
            if (c.change == FrameChange::Vanished) QVERIFY(!slider->hasMark(c.frame, FrameMarkKind::Detected));
            QVERIFY(!slider->isOutdated(c.frame, FrameMarkKind::Vanished));
        }

        auto* dialog = window.findChild<SessionSweepPanel*>();
        const QString text = dialog->summaryText();
        QVERIFY2(text.contains(QString("%1 vanished").arg(r->comparison.vanished)), qPrintable(text));
        QVERIFY2(text.contains("False positives") && !text.contains("no truth.csv"), qPrintable(text));
        QVERIFY2(text.contains("Detection ratio"), qPrintable(text));
        QVERIFY2(text.contains("Compared with " + window.document()->path()), qPrintable(text));

        // The frames behind the numbers are listed: a missed one shows when clicked.
        QCOMPARE(int(r->falsePositiveFrames.size()), r->currentRow.falsePositives);
        QVERIFY(!r->missedFrames.empty());
        auto* list = dialog->findChild<QListWidget*>("changeList");
        const auto found = list->findItems(QString("Frame %1: missed").arg(r->missedFrames.back()), Qt::MatchStartsWith);
        QCOMPARE(found.size(), 1);
        list->scrollToItem(found[0]);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, list->visualItemRect(found[0]).center());
        QCOMPARE(window.navigator()->current(), r->missedFrames.back());

        // The tooltip names the marks of the frame under the cursor and explains the colours.
        const int firstVanished = slider->marks(FrameMarkKind::Vanished).front().frame;
        const QPoint at(slider->tickX(firstVanished), slider->height() / 2);
        QCOMPARE(slider->frameAt(at.x()), firstVanished);
        QHelpEvent help(QEvent::ToolTip, at, slider->mapToGlobal(at));
        QApplication::sendEvent(slider, &help);
        QTRY_VERIFY(QToolTip::isVisible());
        QVERIFY2(QToolTip::text().contains(QString("Frame %1").arg(firstVanished)) && QToolTip::text().contains("vanished"),
                 qPrintable(QToolTip::text()));
        QVERIFY(QToolTip::text().contains("ground truth"));  // the legend lists every kind
        if (const QByteArray dir = qgetenv("OMNITUNE_SHOTS"); !dir.isEmpty())
            for (QWidget* w : QApplication::topLevelWidgets())
                if (w->inherits("QTipLabel")) w->grab().save(QString::fromLocal8Bit(dir) + "/sweep-tooltip.png");
        QToolTip::hideText();

        // Jumping to the next change shows a vanished frame.
        QVERIFY(dialog->nextChange());
        const int shown = window.navigator()->current();
        QVERIFY(slider->hasMark(shown, FrameMarkKind::Vanished));
        QVERIFY(waitForFrame(window, shown));

        if (const QByteArray dir = qgetenv("OMNITUNE_SHOTS"); !dir.isEmpty()) {
            dialog->grab().save(QString::fromLocal8Bit(dir) + "/sweep-panel.png");
            window.grab().save(QString::fromLocal8Bit(dir) + "/sweep-window.png");
        }

        // Any later edit: the marks and the numbers describe an older config and say so.
        QVERIFY(!dialog->isOutdated());
        QVERIFY(!window.document()->setValue("validation.min_circularity_pct", ConfigValue(95.0)));
        QVERIFY(dialog->isOutdated());
        QVERIFY(dialog->findChild<QLabel*>("outdated")->isVisible());
        const int vanished = slider->marks(FrameMarkKind::Vanished).front().frame;
        QVERIFY(slider->isOutdated(vanished, FrameMarkKind::Vanished));
        QVERIFY(slider->hasOutdatedMarks());
        if (const QByteArray dir = qgetenv("OMNITUNE_SHOTS"); !dir.isEmpty()) {
            dialog->grab().save(QString::fromLocal8Bit(dir) + "/sweep-panel-outdated.png");
            window.grab().save(QString::fromLocal8Bit(dir) + "/sweep-window-outdated.png");
        }
        window.document()->undoStack()->setClean();
    }

    void withoutTruthNoFalsePositives()
    {
        const QString session = freshSession();
        QVERIFY(QFile::remove(session + "/truth.csv"));
        MainWindow window;
        window.show();
        QVERIFY(window.openSource(session));
        const auto r = applyInWindow(window);
        QVERIFY(r && r->ok());
        QVERIFY(!r->hasTruth);
        QCOMPARE(r->visited, kDemoFrames);
        const QString text = window.findChild<SessionSweepPanel*>()->summaryText();
        QVERIFY2(text.contains("no truth.csv: mark ground truth to get false positives"), qPrintable(text));
        QVERIFY2(!text.contains("Detection ratio"), qPrintable(text));
        if (const QByteArray dir = qgetenv("OMNITUNE_SHOTS"); !dir.isEmpty())
            window.findChild<SessionSweepPanel*>()->grab().save(QString::fromLocal8Bit(dir) + "/sweep-panel-notruth.png");
        // Detections are marked even with nothing to compare against.
        QCOMPARE(window.navigator()->slider()->marks(FrameMarkKind::Detected).size(),
                 int(std::count_if(r->current.begin(), r->current.end(),
                                   [](const FrameOutcome& o) { return o.detection.found; })));
        window.document()->undoStack()->setClean();
    }

    void cancelButtonStopsTheSweep()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openSource(freshSession()));
        QVERIFY(!window.document()->setValue("validation.min_circularity_pct", ConfigValue(90.0)));
        window.findChild<QAction*>("applyToSession")->trigger();
        auto* dialog = window.findChild<SessionSweepPanel*>();
        QVERIFY(dialog && dialog->isRunning());
        auto* cancel = dialog->findChild<QPushButton*>("cancel");
        QVERIFY(cancel->isVisible());
        QSignalSpy finished(dialog, &SessionSweepPanel::sweepFinished);
        // Cancel at the first progress report the dialog itself receives, as a user would.
        connect(dialog, &SessionSweepPanel::sweepProgress, cancel, [cancel](int done, int) {
            if (done >= 1 && cancel->isEnabled()) QTest::mouseClick(cancel, Qt::LeftButton);
        });
        QVERIFY(finished.wait(60000));
        const auto r = finished.at(0).at(0).value<std::shared_ptr<const SweepResult>>();
        QVERIFY(r->ok());
        QVERIFY2(r->cancelled && r->visited < kDemoFrames, qPrintable(QString::number(r->visited)));
        QVERIFY(dialog->summaryText().contains("Cancelled after"));
        QVERIFY(!cancel->isVisible());
        window.document()->undoStack()->setClean();
    }
};

QTEST_MAIN(SessionSweepTest)
#include "app_session_sweep_test.moc"
