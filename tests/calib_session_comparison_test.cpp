// Comparing two configs' detections frame by frame (calib/SessionComparison): one readable
// row per kind of change, the pairing by frame number and the counts.
#include "calib/eval/SessionComparison.h"

#include <QtTest>

using namespace omnitune;

Q_DECLARE_METATYPE(omnitune::FrameChange)
Q_DECLARE_METATYPE(omnitune::FrameOutcome)

namespace {

FrameOutcome ballAt(int frame, double px, double py)
{
    FrameOutcome o;
    o.frame = frame;
    o.processed = true;
    o.detection.found = true;
    o.detection.px = px;
    o.detection.py = py;
    return o;
}

FrameOutcome noBall(int frame, bool processed = true)
{
    FrameOutcome o;
    o.frame = frame;
    o.processed = processed;
    return o;
}

}  // namespace

class SessionComparisonTest : public QObject {
    Q_OBJECT
private slots:
    void oneFrame_data()
    {
        QTest::addColumn<FrameOutcome>("current");
        QTest::addColumn<FrameOutcome>("saved");
        QTest::addColumn<FrameChange>("change");
        QTest::addColumn<double>("shift");
        QTest::newRow("neither finds a ball") << noBall(3) << noBall(3) << FrameChange::Same << 0.0;
        QTest::newRow("same place") << ballAt(3, 100, 50) << ballAt(3, 100, 50) << FrameChange::Same << 0.0;
        QTest::newRow("re-centred by 3-4-5 px, at the threshold") << ballAt(3, 103, 54) << ballAt(3, 100, 50)
                                                                  << FrameChange::Same << 5.0;
        QTest::newRow("just beyond the threshold") << ballAt(3, 106, 50) << ballAt(3, 100, 50) << FrameChange::Moved << 6.0;
        QTest::newRow("another object") << ballAt(3, 300, 200) << ballAt(3, 100, 200) << FrameChange::Moved << 200.0;
        QTest::newRow("only the current config") << ballAt(3, 100, 50) << noBall(3) << FrameChange::Appeared << 0.0;
        QTest::newRow("only the saved config") << noBall(3) << ballAt(3, 100, 50) << FrameChange::Vanished << 0.0;
        QTest::newRow("current failed on the frame") << noBall(3, false) << ballAt(3, 100, 50) << FrameChange::Vanished
                                                     << 0.0;
        QTest::newRow("both failed") << noBall(3, false) << noBall(3, false) << FrameChange::Same << 0.0;
    }
    void oneFrame()
    {
        QFETCH(FrameOutcome, current);
        QFETCH(FrameOutcome, saved);
        QFETCH(FrameChange, change);
        QFETCH(double, shift);
        const SessionComparison c = compareSessions({current}, {saved});
        QCOMPARE(c.frames.size(), size_t(1));
        QCOMPARE(c.frames[0].frame, 3);
        QCOMPARE(c.frames[0].change, change);
        QCOMPARE(c.frames[0].shiftPx, shift);
        QCOMPARE(c.same + c.changed(), 1);
    }

    void thresholdIsAParameter()
    {
        const ComparisonOptions strict{2.0};
        QCOMPARE(compareSessions({ballAt(0, 103, 54)}, {ballAt(0, 100, 50)}, strict).moved, 1);
        QVERIFY_EXCEPTION_THROWN(compareSessions({}, {}, ComparisonOptions{0.0}), std::invalid_argument);
    }

    void pairsByFrameAndCounts()
    {
        // Saved outcomes in another order, one frame missing on each side.
        const std::vector<FrameOutcome> current = {ballAt(0, 10, 10), noBall(1), ballAt(2, 50, 50), ballAt(3, 80, 80),
                                                   ballAt(4, 10, 10), ballAt(5, 1, 1)};
        const std::vector<FrameOutcome> saved = {ballAt(6, 1, 1), ballAt(4, 10, 10), ballAt(3, 10, 80),
                                                 noBall(2), ballAt(1, 7, 7), ballAt(0, 10, 11)};
        const SessionComparison c = compareSessions(current, saved);
        QCOMPARE(c.frames.size(), size_t(5));  // frame 5 has no saved outcome, frame 6 no current one
        const FrameChange expected[] = {FrameChange::Same, FrameChange::Vanished, FrameChange::Appeared,
                                        FrameChange::Moved, FrameChange::Same};
        for (int i = 0; i < 5; ++i) {
            QCOMPARE(c.frames[i].frame, i);
            QCOMPARE(c.frames[i].change, expected[i]);
        }
        QCOMPARE(c.same, 2);
        QCOMPARE(c.appeared, 1);
        QCOMPARE(c.vanished, 1);
        QCOMPARE(c.moved, 1);
        QCOMPARE(c.changed(), 3);
    }

    void namesForMessages()
    {
        QCOMPARE(QString(frameChangeName(FrameChange::Vanished)), QString("vanished"));
        QCOMPARE(QString(frameChangeName(FrameChange::Moved)), QString("moved"));
    }
};

QTEST_GUILESS_MAIN(SessionComparisonTest)
#include "calib_session_comparison_test.moc"
