// The evaluation statistics (thesis ch. 5) on hand-made outcomes whose numbers can be checked
// by hand.
#include "calib/eval/Evaluation.h"

#include <QtTest>

using namespace omnitune;

namespace {

TruthRow ball(int frame, double x, double y)
{
    TruthRow t;
    t.frame = frame;
    t.ballVisible = true;
    t.xM = x;
    t.yM = y;
    t.robot = RobotPose{0.0, 0.0, M_PI / 2};  // facing field +y: robot frame = field frame
    return t;
}

FrameOutcome seen(int frame, double x, double y, double ms = 5.0)
{
    FrameOutcome o;
    o.frame = frame;
    o.processed = true;
    o.detection.found = true;
    o.detection.xM = x;
    o.detection.yM = y;
    o.timeMs = ms;
    return o;
}

FrameOutcome missed(int frame, bool processed = true)
{
    FrameOutcome o;
    o.frame = frame;
    o.processed = processed;
    o.timeMs = 4.0;
    return o;
}

}  // namespace

class EvaluationTest : public QObject {
    Q_OBJECT
private slots:
    // The per-frame verdict the sweep lists and evaluate() counts.
    void judgesEachFrame()
    {
        const TruthRow ballHere = ball(1, 1.0, 2.0);
        TruthRow noBall;
        noBall.frame = 1;
        QCOMPARE(judge(seen(1, 1.1, 2.0), nullptr), TruthVerdict::Unannotated);
        QCOMPARE(judge(seen(1, 1.1, 2.0), &ballHere), TruthVerdict::Correct);
        QCOMPARE(judge(seen(1, 1.6, 2.0), &ballHere), TruthVerdict::FalsePositive);  // 0.6 m off
        QCOMPARE(judge(missed(1), &ballHere), TruthVerdict::Missed);
        QCOMPARE(judge(missed(1, false), &ballHere), TruthVerdict::Missed);  // unreadable
        QCOMPARE(judge(seen(1, 1.0, 2.0), &noBall), TruthVerdict::FalsePositive);
        QCOMPARE(judge(missed(1), &noBall), TruthVerdict::Correct);
        // A ball more than half hidden (behind a rod) is no ball to find, and a detection at it no
        // false positive; one elsewhere still is.
        const cv::Point2d hidden(1.0, 2.0);
        QCOMPARE(judge(seen(1, 1.1, 2.0), &noBall, {}, hidden), TruthVerdict::AtHiddenBall);
        QCOMPARE(judge(seen(1, 1.6, 2.0), &noBall, {}, hidden), TruthVerdict::FalsePositive);
        QCOMPARE(judge(missed(1), &noBall, {}, hidden), TruthVerdict::Correct);
    }

    void ratioMeanStdAndFalsePositives()
    {
        std::map<int, TruthRow> truth;
        for (int i = 0; i < 4; ++i) truth[i] = ball(i, 1.0, 2.0);
        TruthRow empty;
        empty.frame = 4;
        truth[4] = empty;  // no ball in frame 4
        const std::vector<FrameOutcome> outcomes = {seen(0, 1.1, 2.0, 3.0), seen(1, 0.9, 2.0, 7.0), missed(2),
                                                    seen(3, 3.0, 2.0), seen(4, 0.0, 1.0)};
        const EvaluationRow r = evaluate(outcomes, truth);
        QCOMPARE(r.frames, 5);
        QCOMPARE(r.withBall, 4);
        QCOMPARE(r.correct, 2);              // frame 3 is 2 m off
        QCOMPARE(r.falsePositives, 2);       // frame 3 and the ball-less frame 4
        QCOMPARE(r.detectionRatioPct, 50.0);
        QCOMPARE(r.falsePositivePct, 40.0);
        QVERIFY(r.hasFieldPositions && r.hasDetections);
        QCOMPARE(r.realX, 1.0);
        // Mean and std over every detection in ball frames, outliers included (thesis tables).
        QVERIFY(std::abs(r.meanX - (1.1 + 0.9 + 3.0) / 3) < 1e-9);
        QVERIFY(r.stdX > 0.9);
        QVERIFY(std::abs(r.maxErrorM - 2.0) < 1e-9);
        QCOMPARE(r.timeMinMs, 3.0);
        QCOMPARE(r.timeMaxMs, 7.0);
    }

    void unreadableBallFramesAreMisses()
    {
        std::map<int, TruthRow> truth = {{0, ball(0, 1, 2)}, {1, ball(1, 1, 2)}};
        const EvaluationRow r = evaluate({seen(0, 1, 2), missed(1, false)}, truth);
        QCOMPARE(r.failed, 1);
        QCOMPARE(r.withBall, 2);
        QCOMPARE(r.detectionRatioPct, 50.0);
    }

    void noDetectionMeansNoAverage()
    {
        std::map<int, TruthRow> truth = {{0, ball(0, 1, 2)}};
        const EvaluationRow r = evaluate({missed(0)}, truth);
        QVERIFY(r.hasFieldPositions);
        QVERIFY(!r.hasDetections);
        const std::string md = evaluationMarkdown({r});
        QVERIFY2(md.find("(1.00, 2.00) | n/a | n/a") != std::string::npos, md.c_str());
    }

    void csvQuotesSessionNames()
    {
        EvaluationRow r;
        r.session = "hall A, field 2";
        r.algorithm = "specific";
        const std::string csv = evaluationCsv({r});
        QVERIFY2(csv.find("\"hall A, field 2\",specific") != std::string::npos, csv.c_str());
    }
};

QTEST_GUILESS_MAIN(EvaluationTest)
#include "calib_evaluation_test.moc"
