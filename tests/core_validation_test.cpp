// Candidate validation (thesis 4.4): non-green, non-black and circularity tests, each shown
// rejecting the look-alike it exists for.
#include "DrawnScene.h"
#include "core/Validation.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;
Q_DECLARE_METATYPE(omnitune::RejectReason)

namespace {

// "rejected by runs on (scores 100 / 100 / 92, run-on 40)": for failure messages.
QString verdict(const BallCandidate& c)
{
    return QString("rejected by %1 (scores %2 / %3 / %4, run-on %5)")
        .arg(QString::fromStdString(std::string(rejectReasonName(c.rejected))))
        .arg(c.scores.nonGreenPct)
        .arg(c.scores.nonBlackPct)
        .arg(c.scores.circularityPct)
        .arg(c.scores.runOnPct);
}

// An unvalidated candidate centred on `p`, with the distance and expected radius there.
BallCandidate candidateAt(const EdgeStages& s, cv::Point p)
{
    BallCandidate cand;
    cand.x = p.x;
    cand.y = p.y;
    cand.distancePx = s.geometry.distanceAt(p.x, p.y);
    cand.expectedRadiusPx = s.ball.radiusAt(cand.distancePx);
    return cand;
}

// The scores of a circle of the expected radius centred on `p`.
ValidationScores scoresAt(const EdgeStages& s, cv::Point p, const ValidationOptions& options)
{
    const BallCandidate c = candidateAt(s, p);
    return scoreCircle(c.x, c.y, c.expectedRadiusPx, s.ball.squareSizeAt(c.distancePx), s.classes, s.edges,
                       s.geometry, options);
}

// A candidate at distance/angle validated against a frame built by `draw`.
template <class Draw>
BallCandidate validateAt(double distance, double angle, Draw draw)
{
    const Config c;
    cv::Mat frame = greenField(c);
    const cv::Point2d p = pointAt(c, distance, angle);
    const cv::Point centre(int(std::lround(p.x)), int(std::lround(p.y)));
    draw(frame, c, centre, expectedRadius(c, distance));
    const EdgeStages s(c, frame);
    BallCandidate cand = candidateAt(s, centre);
    validateCandidate(cand, s.classes, s.edges, s.geometry, s.ball, c.validation);
    return cand;
}

}  // namespace

class ValidationTest : public QObject {
    Q_OBJECT
private slots:
    void acceptsABall_data()
    {
        QTest::addColumn<double>("distance");
        QTest::newRow("near, 80 px") << 80.0;
        QTest::newRow("2 m, 175 px") << 175.0;
        QTest::newRow("far, 200 px") << 200.0;
    }
    void acceptsABall()
    {
        QFETCH(double, distance);
        const BallCandidate c = validateAt(distance, 40, [](cv::Mat& f, const Config&, cv::Point p, double r) {
            cv::circle(f, p, int(std::lround(r)), kOrange, cv::FILLED);
        });
        QCOMPARE(c.rejected, RejectReason::None);
        QVERIFY(c.scores.nonGreenPct >= 85);
        QVERIFY(c.scores.nonBlackPct >= 50);
        QVERIFY2(c.scores.circularityPct >= 90, qPrintable(QString::number(c.scores.circularityPct)));
    }

    void rejectsLookAlikes_data()
    {
        QTest::addColumn<int>("shape");
        QTest::addColumn<RejectReason>("expected");
        QTest::newRow("white line crossing") << 0 << RejectReason::NonGreen;
        QTest::newRow("black robot") << 1 << RejectReason::NonBlack;
        QTest::newRow("patch of green") << 2 << RejectReason::NonGreen;
        QTest::newRow("half circle") << 3 << RejectReason::Circularity;
        QTest::newRow("white area edge (not round)") << 4 << RejectReason::Circularity;
        QTest::newRow("line corner") << 5 << RejectReason::Circularity;
    }
    void rejectsLookAlikes()
    {
        QFETCH(int, shape);
        QFETCH(RejectReason, expected);
        const BallCandidate c = validateAt(150, 120, [shape](cv::Mat& f, const Config&, cv::Point p, double r) {
            const int ri = int(std::lround(r));
            switch (shape) {
            case 0:  // two lines crossing at the candidate
                cv::line(f, p - cv::Point(40, 0), p + cv::Point(40, 0), kWhite, 3);
                cv::line(f, p - cv::Point(0, 40), p + cv::Point(0, 40), kWhite, 3);
                break;
            case 1:  // a black robot, round and as big as the ball square
                cv::circle(f, p, ri, kBlack, cv::FILLED);
                break;
            case 2:  // carpet with a small non-green speck: mostly green
                cv::circle(f, p, 1, kOrange, cv::FILLED);
                break;
            case 3:  // half a ball: its upper border merges into a non-green region, no edge there
                cv::circle(f, p, ri, kOrange, cv::FILLED);
                cv::rectangle(f, cv::Rect(p.x - 3 * ri, p.y - 3 * ri, 6 * ri, 3 * ri), kOrange, cv::FILLED);
                break;
            case 4:  // a large white area whose straight border passes near
                cv::rectangle(f, cv::Rect(p.x - 40, p.y - 40, 80, 80), kWhite, cv::FILLED);
                break;
            case 5:  // two lines as wide as the ball meeting at the candidate
                cv::line(f, p, p + cv::Point(40, 25), kWhite, 2 * ri);
                cv::line(f, p, p + cv::Point(-10, 45), kWhite, 2 * ri);
                break;
            }
        });
        QVERIFY2(c.rejected == expected,
                 qPrintable(QString("rejected by %1 (scores %2 / %3 / %4)")
                                .arg(QString::fromStdString(std::string(rejectReasonName(c.rejected))))
                                .arg(c.scores.nonGreenPct)
                                .arg(c.scores.nonBlackPct)
                                .arg(c.scores.circularityPct)));
    }

    void halfCircleScoresAboutHalf()
    {
        const BallCandidate c = validateAt(120, 200, [](cv::Mat& f, const Config&, cv::Point p, double r) {
            const int ri = int(std::lround(r));
            cv::circle(f, p, ri, kOrange, cv::FILLED);
            // The upper half's border is blurred away into a non-green, edge-free region.
            cv::rectangle(f, cv::Rect(p.x - 3 * ri, p.y - 3 * ri, 6 * ri, 3 * ri), kOrange, cv::FILLED);
        });
        QVERIFY2(c.scores.circularityPct > 35 && c.scores.circularityPct < 65, qPrintable(QString::number(c.scores.circularityPct)));
        QCOMPARE(c.rejected, RejectReason::Circularity);
    }

    void tooSmallToValidate()
    {
        const BallCandidate c = validateAt(230, 40, [](cv::Mat& f, const Config&, cv::Point p, double r) {
            cv::circle(f, p, int(std::lround(r)), kOrange, cv::FILLED);
        });
        QVERIFY(c.expectedRadiusPx < Config{}.validation.minRadiusPx);
        QCOMPARE(c.rejected, RejectReason::TooSmall);
    }

    // Far away (205 px, expected radius 4.3 px) the rounded tip of an acute line corner passes the
    // three thesis tests like a ball; the run-on test sees the lines go on beyond the circle.
    void lineCornerRunsOn()
    {
        const BallCandidate c = validateAt(205, 40, [](cv::Mat& f, const Config&, cv::Point p, double r) {
            const int ri = int(std::lround(r));
            // Two lines half as wide as the ball meet 30 degrees apart; their junction is a blob
            // with the ball's radius (simulated frames show such corners 3.1-3.4 m away).
            cv::circle(f, p, ri, kWhite, cv::FILLED);
            cv::line(f, p, p + cv::Point(60, 0), kWhite, ri);
            cv::line(f, p, p + cv::Point(52, 30), kWhite, ri);
        });
        QVERIFY2(c.rejected == RejectReason::RunsOn,
                 qPrintable(verdict(c)));
        QVERIFY(c.scores.runOnPct > Config{}.validation.maxRunOnPct);
    }

    // The same distance, a ball on carpet: nothing of its colour lies beyond its border. Beside
    // a line (a strip of carpet between them) it still passes.
    void ballDoesNotRunOn_data()
    {
        QTest::addColumn<bool>("lineBeside");
        QTest::newRow("on carpet") << false;
        QTest::newRow("beside a line") << true;
    }
    void ballDoesNotRunOn()
    {
        QFETCH(bool, lineBeside);
        const BallCandidate c = validateAt(205, 40, [lineBeside](cv::Mat& f, const Config&, cv::Point p, double r) {
            const int ri = int(std::lround(r));
            if (lineBeside) cv::line(f, p + cv::Point(2 * ri + 2, -40), p + cv::Point(2 * ri + 2, 40), kWhite, ri);
            cv::circle(f, p, ri, kOrange, cv::FILLED);
        });
        QVERIFY2(c.rejected == RejectReason::None,
                 qPrintable(verdict(c)));
        QCOMPARE(c.scores.runOnPct, 0.0);
    }

    // The tuned constants of the circle tests are config keys, and each one is used.
    void runOnReachIsTheConfigs()
    {
        // A white disc alone: at the default reach every ray leaves it onto carpet; at a reach
        // of one radius many rays end inside the disc, so its colour "runs on" along them.
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 150, 0, kWhite);
        const EdgeStages s(c, frame);
        auto score = [&](const ValidationOptions& o) { return scoresAt(s, p, o); };
        QCOMPARE(score(c.validation).runOnPct, 0.0);
        ValidationOptions shortReach = c.validation;
        shortReach.runOnReach = 1.0;
        QVERIFY2(score(shortReach).runOnPct > c.validation.maxRunOnPct,
                 qPrintable(QString::number(score(shortReach).runOnPct)));
    }

    void minUsableRayShareIsTheConfigs()
    {
        // Half the ball behind the mask (a robot part): the rays left are judged by default, not
        // when every ray must be usable.
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 150, 0);
        const int r = int(std::lround(expectedRadius(c, 150)));
        c.mask = cv::Mat(frame.size(), CV_8UC1, cv::Scalar(255));
        cv::rectangle(c.mask, cv::Rect(p.x - 3 * r, p.y - 3 * r, 3 * r + r / 2, 6 * r), cv::Scalar(0), cv::FILLED);
        const EdgeStages s(c, frame);
        auto score = [&](const ValidationOptions& o) { return scoresAt(s, p, o); };
        QVERIFY2(score(c.validation).circularityPct > 30, qPrintable(QString::number(score(c.validation).circularityPct)));
        ValidationOptions allRays = c.validation;
        allRays.minUsableRayShare = 1.0;
        QCOMPARE(score(allRays).circularityPct, 0.0);
    }

    void beyondEdgePxIsTheConfigs()
    {
        // A ball inside a white ring with a thin strip of carpet between them: just beyond its
        // border lies carpet (a ball), a few pixels farther the ring (no carpet: not a border).
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 120, 0);
        const int r = int(std::lround(expectedRadius(c, 120)));
        cv::circle(frame, p, r + 5, kWhite, 3);
        const EdgeStages s(c, frame);
        auto score = [&](const ValidationOptions& o) { return scoresAt(s, p, o); };
        QVERIFY2(score(c.validation).circularityPct > 70, qPrintable(QString::number(score(c.validation).circularityPct)));
        ValidationOptions farther = c.validation;
        farther.beyondEdgePx = 5.0;
        QVERIFY2(score(farther).circularityPct < 30, qPrintable(QString::number(score(farther).circularityPct)));
    }

    void thresholdsAreTheConfigs()
    {
        // The same orange ball fails when the circularity threshold is raised above its score.
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 150, 0);
        const EdgeStages s(c, frame);
        BallCandidate cand = candidateAt(s, p);
        validateCandidate(cand, s.classes, s.edges, s.geometry, s.ball, c.validation);
        QCOMPARE(cand.rejected, RejectReason::None);
        c.validation.minNonBlackPct = 100.1;
        cand.rejected = RejectReason::None;
        validateCandidate(cand, s.classes, s.edges, s.geometry, s.ball, c.validation);
        QCOMPARE(cand.rejected, RejectReason::NonBlack);
    }
};

QTEST_GUILESS_MAIN(ValidationTest)
#include "core_validation_test.moc"
