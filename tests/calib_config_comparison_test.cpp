// Two configs over one session (calib/eval/ConfigComparisonRun), Qt-free, on the simulated demo
// session (read only): the same config twice changes nothing and matches the batch evaluation; a
// stricter config makes exactly the frames it loses "vanished"; a cancel stops early with a
// consistent partial result; a saved config that cannot be loaded or a missing source is a
// message, not a crash; and the Markdown report names both configs and the changed frames.
#include "calib/eval/BatchRun.h"
#include "calib/eval/ConfigComparisonReport.h"
#include "calib/eval/ConfigComparisonRun.h"
#include "calib/session/SessionReader.h"
#include "calib/source/SessionSource.h"
#include "core/ConfigParser.h"

#include <QtTest>

using namespace omnitune;

namespace {

const std::string kDemo = OMNITUNE_SOURCE_DIR "/sessions/demo";
constexpr int kDemoFrames = 24;

Config demoConfig() { return loadConfig(kDemo + "/config.yml").config; }

std::map<int, TruthRow> demoTruth() { return SessionReader::open(kDemo).reader->truth(); }

// Cancels once `after` frames are done.
class CancelAfter : public Progress {
public:
    explicit CancelAfter(int after, int total) : after_(after), total_(total) {}
    void update(double percent) override { done_ = int(std::lround(percent * total_ / 100.0)); }
    bool isCancelRequested() const override { return done_ >= after_; }

private:
    int after_, total_, done_ = 0;
};

ConfigComparisonRequest demoRequest()
{
    ConfigComparisonRequest request;
    request.sourcePath = kDemo;
    request.current = demoConfig();
    request.savedConfigPath = kDemo + "/config.yml";
    request.truth = demoTruth();
    return request;
}

}  // namespace

class ConfigComparisonTest : public QObject {
    Q_OBJECT
private slots:
    void sameConfigChangesNothingAndMatchesTheBatch()
    {
        const ConfigComparisonRequest request = demoRequest();
        QVERIFY(!request.truth.empty());
        ConfigComparisonResult r;
        runConfigComparison(request, r);
        QVERIFY2(r.ok(), r.error.c_str());
        QCOMPARE(r.total, kDemoFrames);
        QCOMPARE(r.visited, kDemoFrames);
        QVERIFY(r.hasTruth && r.hasSaved && r.savedIsCurrent);
        QCOMPARE(int(r.comparison.frames.size()), kDemoFrames);
        QCOMPARE(r.comparison.changed(), 0);

        // What omnitune-eval computes on its own.
        SessionOpen opened = SessionReader::open(kDemo);
        SessionSource source(*opened.reader);
        Pipeline pipeline(request.current);
        std::vector<FrameOutcome> outcomes;
        runBatch(source, pipeline, [&](int i, const Frame*, const PipelineResult& p) { outcomes.push_back(outcomeOf(i, p)); });
        const EvaluationRow expected = evaluate(outcomes, request.truth);
        QCOMPARE(r.currentRow.correct, expected.correct);
        QCOMPARE(r.currentRow.withBall, expected.withBall);
        QCOMPARE(r.currentRow.falsePositives, expected.falsePositives);
        QCOMPARE(r.savedRow.correct, expected.correct);
        QCOMPARE(int(r.falsePositiveFrames.size()), expected.falsePositives);
        QVERIFY(r.currentRow.detectionRatioPct >= 90.0);
    }

    void stricterConfigLosesExactlyTheVanishedFrames()
    {
        ConfigComparisonRequest request = demoRequest();
        request.savedConfig = demoConfig();  // loaded by the caller: the path only names it
        request.current.validation.minCircularityPct = 100.0;
        request.current.validation.circleFit = false;  // the thesis' band: a fitted circle takes every demo ball
        ConfigComparisonResult r;
        runConfigComparison(request, r);
        QVERIFY2(r.ok(), r.error.c_str());
        QVERIFY(r.hasSaved && !r.savedIsCurrent);
        QCOMPARE(int(r.saved.size()), kDemoFrames);
        QVERIFY(r.comparison.vanished > 0);
        QCOMPARE(r.comparison.appeared, 0);
        QVERIFY(r.currentRow.correct < r.savedRow.correct);
        for (int i = 0; i < kDemoFrames; ++i) {
            const bool lost = r.saved[i].detection.found && !r.current[i].detection.found;
            QCOMPARE(r.comparison.frames[i].change == FrameChange::Vanished, lost);
        }

        const std::string md = configComparisonMarkdown(r, "strict.yml", "config.yml");
        QVERIFY2(md.find("| strict.yml | 24 |") != std::string::npos, md.c_str());
        QVERIFY2(md.find("| config.yml | 24 |") != std::string::npos, md.c_str());
        QVERIFY2(md.find(std::to_string(r.comparison.vanished) + " vanished") != std::string::npos, md.c_str());
        std::string vanished = "- vanished (only config.yml finds a ball): ";
        for (const FrameComparison& c : r.comparison.frames)
            if (c.change == FrameChange::Vanished) vanished += std::to_string(c.frame) + " ";
        vanished.pop_back();
        QVERIFY2(md.find(vanished + "\n") != std::string::npos, md.c_str());
    }

    void cancelStopsEarly()
    {
        ConfigComparisonRequest request = demoRequest();
        request.current.validation.minCircularityPct = 90.0;  // both configs run
        CancelAfter progress(5, kDemoFrames);
        ConfigComparisonResult r;
        runConfigComparison(request, r, &progress);
        QVERIFY(r.ok());
        QVERIFY(r.cancelled);
        QCOMPARE(r.visited, 5);
        QCOMPARE(int(r.current.size()), 5);
        QCOMPARE(int(r.saved.size()), 5);
        QCOMPARE(r.currentRow.frames, 5);
        QVERIFY(configComparisonMarkdown(r, "a", "b").find("Cancelled after 5 frames") != std::string::npos);
    }

    void unusableInputsAreMessages()
    {
        ConfigComparisonRequest request = demoRequest();
        request.savedConfigPath = kDemo + "/no-such-config.yml";
        ConfigComparisonResult r;
        runConfigComparison(request, r);
        QVERIFY(r.ok());
        QVERIFY(!r.hasSaved);
        QVERIFY2(r.savedNote.find("no-such-config.yml") != std::string::npos, r.savedNote.c_str());
        QCOMPARE(int(r.current.size()), kDemoFrames);  // the current config still ran

        request.savedConfigPath.clear();
        runConfigComparison(request, r);
        QVERIFY(!r.hasSaved);
        QVERIFY2(r.savedNote.find("never been saved") != std::string::npos, r.savedNote.c_str());

        request.sourcePath = kDemo + "-missing";
        runConfigComparison(request, r);
        QVERIFY(!r.ok());
        QVERIFY2(r.error.find("demo-missing") != std::string::npos, r.error.c_str());

        request = demoRequest();
        request.current.edges.cannyLow = 200;  // above canny_high: the pipeline refuses it
        request.current.edges.cannyHigh = 100;
        runConfigComparison(request, r);
        QVERIFY(!r.ok());
        QVERIFY2(r.error.find("cannot run") != std::string::npos, r.error.c_str());
    }
};

QTEST_GUILESS_MAIN(ConfigComparisonTest)
#include "calib_config_comparison_test.moc"
