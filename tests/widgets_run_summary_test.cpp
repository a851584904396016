// The status bar's timing line says when a noisy frame was blurred before segmentation
// (denoise.above_noise), and its tooltip gives the frame's measured noise: the segmented pane
// then differs from the acquired one, and a team tuning denoise needs the number.
#include "widgets/PipelineRunner.h"
#include "widgets/RunSummary.h"

#include <QLabel>
#include <QtTest>

using namespace omnitune;

class RunSummaryTest : public QObject {
    Q_OBJECT

private slots:
    void marksABlurredFrame()
    {
        RunSummary summary;
        PipelineRun run;
        run.frameIndex = 3;
        run.result.timings.totalMs = 4.0;
        run.result.frameNoise = 5.4;
        run.result.denoised = true;
        summary.showResult(run);
        QVERIFY2(summary.timingLabel()->text().contains("blurred"), qPrintable(summary.timingLabel()->text()));
        QVERIFY(summary.timingLabel()->toolTip().contains("5.4"));

        run.result.frameNoise = 2.1;
        run.result.denoised = false;
        summary.showResult(run);
        QVERIFY(!summary.timingLabel()->text().contains("blurred"));
        QVERIFY(summary.timingLabel()->toolTip().contains("2.1 levels: not blurred"));

        run.result.frameNoise = 0.0;
        summary.showResult(run);
        QVERIFY(summary.timingLabel()->toolTip().contains("not measured"));
    }
};

QTEST_MAIN(RunSummaryTest)
#include "widgets_run_summary_test.moc"
