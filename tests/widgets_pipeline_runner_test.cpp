// The pipeline runner decodes frames on its own thread (the window never blocks on a PNG),
// re-runs a config change on the frame it already decoded, reports an unreadable frame as
// such, and hands back the tag of the source a run came from.
#include "widgets/PipelineRunner.h"
#include "calib/sim/SceneSimulator.h"

#include <QtTest>

#include <atomic>

using namespace omnitune;

namespace {

// Frames rendered once by the simulator; frame 1 "does not decode". Records where it is read.
class StubSource : public FrameSource {
public:
    StubSource() : frame_(SceneSimulator(Config{}).render(SceneOptions{})) {}
    std::string description() const override { return "stub"; }
    bool isSeekable() const override { return true; }
    int frameCount() const override { return 3; }
    cv::Size frameSize() const override { return frame_.size(); }

    std::atomic<int> reads{0};
    std::atomic<QThread*> readOn{nullptr};

protected:
    std::optional<FrameError> readAt(int index, Frame& out) override
    {
        ++reads;
        readOn = QThread::currentThread();
        if (index == 1) return FrameError{FrameErrorKind::Unreadable, index, "000001.png", "000001.png does not decode"};
        out.image = frame_.clone();
        out.format = PixelFormat::Bgr8;
        return std::nullopt;
    }

private:
    cv::Mat frame_;
};

std::shared_ptr<const PipelineRun> runOnce(PipelineRunner& runner, std::shared_ptr<FrameSource> source, quint64 tag,
                                           int index, const Config& config, quint64 generation)
{
    QSignalSpy spy(&runner, &PipelineRunner::finished);
    runner.request(std::move(source), tag, index, config, generation);
    if (!spy.wait(20000)) return nullptr;
    return spy.at(0).at(0).value<std::shared_ptr<const PipelineRun>>();
}

}  // namespace

class PipelineRunnerTest : public QObject {
    Q_OBJECT
private slots:
    void readsOffTheGuiThreadAndReusesTheFrame()
    {
        PipelineRunner runner;
        auto source = std::make_shared<StubSource>();
        Config config;
        const auto first = runOnce(runner, source, 7, 0, config, 1);
        QVERIFY(first && first->error.isEmpty());
        QCOMPARE(first->sourceTag, quint64(7));
        QVERIFY(source->readOn.load() != nullptr && source->readOn.load() != QThread::currentThread());
        QVERIFY(!first->result.stages.acquired.empty());
        // The window explains every verdict (Pipeline::setExplainRejections): what a colour test
        // refused in validation still has its shape measured for the candidate table.
        int shapedColourRefusals = 0;
        for (const BallCandidate& c : first->result.candidates)
            shapedColourRefusals += (c.rejected == RejectReason::NonGreen || c.rejected == RejectReason::NonBlack) &&
                                    c.scores.shapeMeasured;
        QVERIFY(shapedColourRefusals > 0);

        config.edges.cannyHigh = 200;  // a threshold edit re-runs the frame without decoding it again
        const auto second = runOnce(runner, source, 7, 0, config, 2);
        QVERIFY(second && second->error.isEmpty());
        QCOMPARE(source->reads.load(), 1);
        QCOMPARE(second->config.edges.cannyHigh, 200);
    }

    void unreadableFrameIsReportedAsSuch()
    {
        PipelineRunner runner;
        auto source = std::make_shared<StubSource>();
        const auto run = runOnce(runner, source, 1, 1, Config{}, 1);
        QVERIFY(run);
        QVERIFY(run->frameUnreadable);
        QVERIFY(run->error.contains("000001.png"));
        const auto next = runOnce(runner, source, 1, 2, Config{}, 1);  // and the next frame still runs
        QVERIFY(next && !next->frameUnreadable && next->result.ok());
    }
};

QTEST_MAIN(PipelineRunnerTest)
#include "widgets_pipeline_runner_test.moc"
