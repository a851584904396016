// The overlay's candidate label ("A3 98/100/96") and the pane tooltip's explanation: the failed
// test stands out in bold against the threshold the candidate was judged by, which for the
// circularity depends on the candidate (validation.min_circularity_clear_pct in the clear).
#include "widgets/CandidateLabel.h"

#include <QtTest>

using namespace omnitune;

namespace {

// A specific-Hough candidate in radial area 3 (index 2) of ~10 px, rejected on circularity.
BallCandidate roundish(double nonBlackPct, double circularityPct)
{
    BallCandidate c;
    c.area = 2;
    c.radiusPx = 10.4;
    c.expectedRadiusPx = 10.4;
    c.scores.nonGreenPct = 97.6;
    c.scores.nonBlackPct = nonBlackPct;
    c.scores.circularityPct = circularityPct;
    c.scores.fitRadiusPx = 10.6;  // the fit agrees with the expected size
    c.scores.squareMeasured = c.scores.shapeMeasured = true;
    c.rejected = RejectReason::Circularity;
    return c;
}

}  // namespace

class CandidateLabelTest : public QObject {
    Q_OBJECT
private slots:
    void labelIsAreaAndScores() { QCOMPARE(candidateLabel(roundish(100, 96.2)), QStringLiteral("A3 98/100/96")); }

    void circularityIsJudgedByTheCandidatesThreshold_data()
    {
        QTest::addColumn<double>("nonBlackPct");
        QTest::addColumn<double>("circularityPct");
        QTest::addColumn<QString>("line");
        QTest::addColumn<bool>("failed");
        QTest::newRow("in the clear, 62 % passes 60 %") << 100.0 << 62.0 << "circularity 62 % (min 60 %)" << false;
        QTest::newRow("in the clear, 58 % fails 60 %") << 100.0 << 58.0 << "circularity 58 % (min 60 %)" << true;
        QTest::newRow("beside a robot, 67 % fails 70 %") << 50.0 << 67.0 << "circularity 67 % (min 70 %)" << true;
    }
    void circularityIsJudgedByTheCandidatesThreshold()
    {
        QFETCH(double, nonBlackPct);
        QFETCH(double, circularityPct);
        QFETCH(QString, line);
        QFETCH(bool, failed);
        const QString text = candidateExplanation(roundish(nonBlackPct, circularityPct), ValidationOptions{});
        QVERIFY2(text.contains(line), qPrintable(text));
        QCOMPARE(text.contains("<b>" + line + "</b>"), failed);
        QVERIFY2(text.contains("radial area 3"), qPrintable(text));
    }

    // A prefilter refusal, or a colour refusal on a pipeline that does not explain: the shape
    // was never measured, so the label shows "-" (as the table does), not a failing 0.
    void unmeasuredShapeIsADash()
    {
        BallCandidate c = roundish(100, 0);
        c.scores.nonGreenPct = 41.2;
        c.scores.shapeMeasured = false;
        c.rejected = RejectReason::NonGreen;
        QCOMPARE(candidateLabel(c), QStringLiteral("A3 41/100/-"));
        const QString text = candidateExplanation(c, ValidationOptions{});
        QVERIFY2(text.contains("circularity not measured"), qPrintable(text));
        QVERIFY2(!text.contains("<b>circularity"), qPrintable(text));
        QVERIFY2(text.contains("<b>non-green 41 %"), qPrintable(text));
        c.scores.squareMeasured = false;
        QCOMPARE(candidateLabel(c), QStringLiteral("A3 -/-/-"));
    }
};

QTEST_GUILESS_MAIN(CandidateLabelTest)
#include "widgets_candidate_label_test.moc"
