// Candidate validation (thesis 4.4): non-green, non-black and circularity tests, each shown
// rejecting the look-alike it exists for.
#include "DrawnCandidate.h"
#include "core/ConfigSchema.h"
#include "core/FitRecentre.h"
#include "core/FrameColour.h"
#include "core/GreenPanelTest.h"
#include "core/Validation.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;
Q_DECLARE_METATYPE(omnitune::RejectReason)

namespace {

// "rejected by runs on (scores 100 / 100 / 92, run-on 40)": for failure messages.
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

// A candidate at `centre` validated on `frame` with the frame's colours, under `c`.
BallCandidate validateFrame(const Config& c, const cv::Mat& frame, cv::Point centre)
{
    const EdgeStages s(c, frame);
    BallCandidate cand = candidateAt(s, centre);
    const FrameColour colour(frame, PixelFormat::Bgr8);
    validateCandidate(cand, s.classes, s.edges, s.geometry, s.ball, c.validation, &colour);
    return cand;
}

// Blurs `frame` along x by `length` px (a ball rolling across the image) and adds sensor noise.
void blurAndNoise(cv::Mat& frame, int length, double sigma)
{
    const cv::Mat kernel = cv::Mat::ones(1, length, CV_32F) / float(length);
    cv::filter2D(frame, frame, -1, kernel);
    cv::Mat noise(frame.size(), CV_16SC3);
    cv::theRNG().state = 7;
    cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(sigma));
    cv::Mat f16;
    frame.convertTo(f16, CV_16SC3);
    f16 += noise;
    f16.convertTo(frame, CV_8UC3);
}

// Green panels of a green-and-white ball: not the carpet's green (hue 44 against 60, more
// saturated), but inside the green class.
const cv::Scalar kPanelGreen(30, 200, 120);

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

    // validateCandidate(stopAtColour), the recentre's: a candidate the colour tests refuse
    // keeps that verdict without its shape being measured; any other is validated in full.
    void stopAtColourKeepsTheVerdict_data()
    {
        QTest::addColumn<int>("shape");
        QTest::addColumn<RejectReason>("expected");
        QTest::newRow("ball") << 0 << RejectReason::None;
        QTest::newRow("black robot") << 1 << RejectReason::NonBlack;
        QTest::newRow("half circle") << 2 << RejectReason::Circularity;
    }
    void stopAtColourKeepsTheVerdict()
    {
        QFETCH(int, shape);
        QFETCH(RejectReason, expected);
        const Config c;
        cv::Mat frame = greenField(c);
        const cv::Point2d at = pointAt(c, 150, 120);
        const cv::Point p(int(std::lround(at.x)), int(std::lround(at.y)));
        const int ri = int(std::lround(expectedRadius(c, 150)));
        cv::circle(frame, p, ri, shape == 1 ? kBlack : kOrange, cv::FILLED);
        if (shape == 2) cv::rectangle(frame, cv::Rect(p.x - 3 * ri, p.y - 3 * ri, 6 * ri, 3 * ri), kOrange, cv::FILLED);
        const EdgeStages s(c, frame);
        BallCandidate full = candidateAt(s, p);
        BallCandidate stopped = full;
        validateCandidate(full, s.classes, s.edges, s.geometry, s.ball, c.validation);
        validateCandidate(stopped, s.classes, s.edges, s.geometry, s.ball, c.validation, nullptr, defaultColourRoles(),
                          true);
        QCOMPARE(full.rejected, expected);
        QCOMPARE(stopped.rejected, expected);
        QCOMPARE(stopped.scores.nonBlackPct, full.scores.nonBlackPct);
        if (expected == RejectReason::NonBlack) {
            QVERIFY(full.scores.circularityPct > 50.0);  // a round robot: its shape was measured
            QCOMPARE(stopped.scores.circularityPct, 0.0);
        } else {
            QCOMPARE(stopped.scores.circularityPct, full.scores.circularityPct);
        }
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
        allRays.maskedRaysUnknown = false;  // else rays into the mask are left out, not missed
        QCOMPARE(score(allRays).circularityPct, 0.0);
    }

    // A circle whose border leads into a robot's black most of the way round (inside a robot's
    // body, at its marker band) is not judged on the few rays left; a ball half in front of a
    // robot is (validation.min_unoccluded_ray_share). Off, both are judged on their carpet side.
    void minUnoccludedRayShareIsTheConfigs_data()
    {
        QTest::addColumn<double>("carpetDegrees");
        QTest::addColumn<bool>("judged");
        QTest::newRow("carpet on 105 degrees") << 105.0 << false;
        QTest::newRow("carpet on 180 degrees") << 180.0 << true;
    }
    void minUnoccludedRayShareIsTheConfigs()
    {
        QFETCH(double, carpetDegrees);
        QFETCH(bool, judged);
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point2d q = pointAt(c, 150, 30);
        const cv::Point p(int(std::lround(q.x)), int(std::lround(q.y)));
        const int r = int(std::lround(expectedRadius(c, 150)));
        cv::circle(frame, p, 4 * r, kBlack, cv::FILLED);
        cv::ellipse(frame, p, cv::Size(4 * r, 4 * r), 0, 0, carpetDegrees, kGreen, cv::FILLED);
        QCOMPARE(drawBall(frame, c, 150, 30), p);
        const EdgeStages s(c, frame);
        auto score = [&](const ValidationOptions& o) { return scoresAt(s, p, o).circularityPct; };
        QVERIFY2((score(c.validation) > 50) == judged, qPrintable(QString::number(score(c.validation))));
        ValidationOptions off = c.validation;
        off.minUnoccludedRayShare = 0.0;
        QVERIFY2(score(off) > 50, qPrintable(QString::number(score(off))));
    }

    // A maximum a few pixels off a ball's centre is refused as a circle off the model, though the
    // circle fitted to its border is the ball's; moved to the fitted centre it passes
    // (validation.refit_recentre). With 0 it stays refused.
    void offCentreMaximumMovesToItsFit()
    {
        const Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 150, 30);
        const EdgeStages s(c, frame);
        BallCandidate off = candidateAt(s, p + cv::Point(3, 2));
        validateCandidate(off, s.classes, s.edges, s.geometry, s.ball, c.validation);
        QVERIFY2(off.rejected == RejectReason::Circularity && off.scores.fitRadiusPx > 0, qPrintable(verdict(off)));
        auto recentre = [&](std::vector<BallCandidate>& list, const ValidationOptions& o) {
            return recentreOnFits(list, list.size(), s.classes, s.edges, s.geometry, s.ball, o, nullptr,
                                  defaultColourRoles(), false);
        };
        std::vector<BallCandidate> list{off};
        ValidationOptions never = c.validation;
        never.refitRecentre = 0;
        QCOMPARE(recentre(list, never), 0);
        QCOMPARE(list[0].x, off.x);
        ValidationOptions tooFar = c.validation;  // the ball's expected radius is under the minimum
        tooFar.refitMinRadiusPx = expectedRadius(c, 150) + 1.0;
        QCOMPARE(recentre(list, tooFar), 0);
        QCOMPARE(list[0].x, off.x);
        QVERIFY(expectedRadius(c, 150) - 1.0 >= c.validation.refitMinRadiusPx);
        QCOMPARE(recentre(list, c.validation), 1);
        QVERIFY2(list[0].rejected == RejectReason::None, qPrintable(verdict(list[0])));
        QVERIFY(list[0].move == CandidateMove::ToCircleFit);  // the window's table says where it came from
        QCOMPARE(list[0].searchX, off.x);
        QCOMPARE(list[0].searchY, off.y);
        QCOMPARE(list[0].radiusPx, list[0].expectedRadiusPx);  // a specific candidate's circle is the expected one
        QVERIFY2(std::hypot(list[0].x - p.x, list[0].y - p.y) <= 1.5,
                 qPrintable(QString("moved to (%1, %2), ball at (%3, %4)").arg(list[0].x).arg(list[0].y).arg(p.x).arg(p.y)));
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
        farther.circleFit = false;  // the fit finds the ring's outer border (and rejects its radius)
        farther.beyondEdgePx = 5.0;
        QVERIFY2(score(farther).circularityPct < 30, qPrintable(QString::number(score(farther).circularityPct)));
    }

    void borderBlendPxIsTheConfigs()
    {
        // A ball inside a 3 px halo of a green that is not the carpet's (the blend of ball and
        // carpet colours at a blurred border): its border leads into carpet within the blend
        // width, so the fit finds the ball's own radius; with no blend allowed the border moves
        // out to where the carpet's own green starts.
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 120, 0, kWhite);
        const int r = int(std::lround(expectedRadius(c, 120)));
        cv::circle(frame, p, r + 2, kPanelGreen, 3);
        const BallCandidate blend = validateFrame(c, frame, p);
        c.validation.borderBlendPx = 0;
        const BallCandidate none = validateFrame(c, frame, p);
        QVERIFY2(std::abs(blend.scores.fitRadiusPx - r) < 1.5, qPrintable(verdict(blend)));
        QVERIFY2(none.scores.fitRadiusPx > blend.scores.fitRadiusPx + 1.5 || none.scores.circularityPct < 50,
                 qPrintable(verdict(none)));
    }

    void carpetRingIsTheConfigs()
    {
        // A green-and-white ball on a patch of its panels' green (a worn carpet patch) out to
        // three radii: measured in the default ring, the carpet is that green and the panels are
        // carpet (non-green fails); measured farther out, the panels are ball.
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point2d at = pointAt(c, 130, 200);
        const cv::Point p(int(std::lround(at.x)), int(std::lround(at.y)));
        const int r = int(std::lround(expectedRadius(c, 130)));
        cv::circle(frame, p, 3 * r, kPanelGreen, cv::FILLED);
        drawBall(frame, c, 130, 200, kWhite);
        for (int k = 0; k < 4; ++k)
            cv::ellipse(frame, p, cv::Size(r, r), 0, 90.0 * k, 90.0 * k + 45.0, kPanelGreen, cv::FILLED);
        const BallCandidate near = validateFrame(c, frame, p);
        QVERIFY2(near.rejected == RejectReason::NonGreen, qPrintable(verdict(near)));
        c.validation.carpetRingInner = 3.5;
        c.validation.carpetRingOuter = 5.0;
        const BallCandidate far = validateFrame(c, frame, p);
        QVERIFY2(far.scores.nonGreenPct > c.validation.minNonGreenPct, qPrintable(verdict(far)));
        // An empty or inverted ring is refused when the config is checked.
        c.validation.carpetRingOuter = 3.5;
        bool refused = false;
        for (const ConfigIssue& i : checkConfig(c)) refused = refused || i.key == "validation.carpet_ring_inner";
        QVERIFY(refused);
    }

    // A ball in the shade of an unevenly lit hall: the carpet around it at 60 % of the frame's,
    // the ball's own colour dark enough to be black against the whole frame's carpet (the colour
    // table's relative black) but not against the carpet beside it. black_by_local_carpet passes
    // it; off, the non-black test rejects it. Robots stay black either way.
    void blackByLocalCarpet()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point2d at = pointAt(c, 130, 60);
        const cv::Point p(int(std::lround(at.x)), int(std::lround(at.y)));
        const int r = int(std::lround(expectedRadius(c, 130)));
        cv::circle(frame, p, 5 * r, kGreen * 0.6, cv::FILLED);
        drawBall(frame, c, 130, 60, cv::Scalar(0, 25, 50));  // a shaded orange, V 50
        const BallCandidate local = validateFrame(c, frame, p);
        QVERIFY2(local.rejected == RejectReason::None, qPrintable(verdict(local)));
        c.validation.blackByLocalCarpet = false;
        const BallCandidate global = validateFrame(c, frame, p);
        QVERIFY2(global.rejected == RejectReason::NonBlack, qPrintable(verdict(global)));
        // A black robot part in the same shade is black against the local carpet too.
        c.validation.blackByLocalCarpet = true;
        drawBall(frame, c, 130, 60, kBlack * 0.6);
        const BallCandidate robot = validateFrame(c, frame, p);
        QVERIFY2(robot.rejected == RejectReason::NonBlack, qPrintable(verdict(robot)));
    }

    // Half the ball behind a masked rod: judged on its visible half (rays that run into the
    // mask are left out); with masked_rays_unknown off those rays are misses and it fails.
    void ballHalfBehindMaskedRod()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 150, 30);
        const int r = int(std::lround(expectedRadius(c, 150)));
        // A rod 2r wide whose edge passes r/3 left of the centre hides ~40 % of the ball.
        c.mask = cv::Mat(frame.size(), CV_8UC1, cv::Scalar(255));
        cv::rectangle(c.mask, cv::Rect(p.x - r / 3 - 2 * r, 0, 2 * r, frame.rows), cv::Scalar(0), cv::FILLED);
        cv::rectangle(frame, cv::Rect(p.x - r / 3 - 2 * r, 0, 2 * r, frame.rows), kBlack, cv::FILLED);
        const BallCandidate on = validateFrame(c, frame, p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
        c.validation.maskedRaysUnknown = false;
        const BallCandidate off = validateFrame(c, frame, p);
        QVERIFY2(off.rejected == RejectReason::Circularity, qPrintable(verdict(off)));
    }

    // A red ball (no class of its own) partly hidden by a robot's magenta marker band: ball and
    // band are one non-green blob, so the rays into the band find no border. They are left out
    // like rays into the robot's black (marker_rays_unknown); off, they are misses and it fails.
    void ballHalfBehindRobotMarker()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 150, 30, cv::Scalar(60, 60, 200));
        const int r = int(std::lround(expectedRadius(c, 150)));
        const cv::Scalar magenta(200, 30, 210);
        cv::rectangle(frame, cv::Rect(p.x - r / 3 - 3 * r, p.y - 4 * r, 3 * r, 8 * r), magenta, cv::FILLED);
        const BallCandidate on = validateFrame(c, frame, p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
        c.validation.markerRaysUnknown = false;
        const BallCandidate off = validateFrame(c, frame, p);
        QVERIFY2(off.rejected == RejectReason::Circularity, qPrintable(verdict(off)));
    }

    // A ball blurred by 7 px of motion, with sensor noise (sigma 6), drawn 2-3 px larger than the
    // ball model expects (a model 2-3 px off on a real camera): the fitted circle passes it, the
    // thesis' band around the expected radius does not.
    void blurredNoisyBallOffModelPassesTheFit_data()
    {
        QTest::addColumn<double>("distance");
        QTest::addColumn<int>("modelError");
        QTest::newRow("1 m, 3 px larger") << 100.0 << 3;
        QTest::newRow("2 m, 2 px larger") << 160.0 << 2;
    }
    void blurredNoisyBallOffModelPassesTheFit()
    {
        QFETCH(double, distance);
        QFETCH(int, modelError);
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point2d q = pointAt(c, distance, 70);
        const cv::Point p(int(std::lround(q.x)), int(std::lround(q.y)));
        cv::circle(frame, p, int(std::lround(expectedRadius(c, distance))) + modelError, kOrange, cv::FILLED);
        blurAndNoise(frame, 7, 6.0);
        const BallCandidate fit = validateFrame(c, frame, p);
        QVERIFY2(fit.rejected == RejectReason::None, qPrintable(verdict(fit)));
        QVERIFY2(std::abs(fit.scores.fitRadiusPx - fit.expectedRadiusPx - modelError) < 1.5,
                 qPrintable(QString::number(fit.scores.fitRadiusPx)));
        c.validation.circleFit = false;
        const BallCandidate band = validateFrame(c, frame, p);
        QVERIFY2(band.rejected == RejectReason::Circularity, qPrintable(verdict(band)));
    }

    // What the wider fit must still reject: a straight edge and a corner of a non-black object
    // (a robot's cover, a poster) and a disc twice the expected size.
    void circleFitRejectsEdgesAndWrongSizes_data()
    {
        QTest::addColumn<int>("shape");
        QTest::newRow("straight edge") << 0;
        QTest::newRow("corner of a square") << 1;
        QTest::newRow("disc of twice the radius") << 2;
        QTest::newRow("disc of half the radius") << 3;
    }
    void circleFitRejectsEdgesAndWrongSizes()
    {
        QFETCH(int, shape);
        const BallCandidate c = validateAt(120, 150, [shape](cv::Mat& f, const Config&, cv::Point p, double r) {
            const int ri = int(std::lround(r));
            const cv::Scalar cover(200, 120, 60);  // blue-grey, neither green nor black
            switch (shape) {
            case 0: cv::rectangle(f, cv::Rect(p.x - 60, p.y - ri / 2, 120, 80), cover, cv::FILLED); break;
            case 1: cv::rectangle(f, cv::Rect(p.x - ri, p.y - ri, 80, 80), cover, cv::FILLED); break;
            case 2: cv::circle(f, p, 2 * ri, kOrange, cv::FILLED); break;
            case 3: cv::circle(f, p, ri / 2, kOrange, cv::FILLED); break;
            }
        });
        QVERIFY2(c.rejected != RejectReason::None, qPrintable(verdict(c)));
    }

    // A green-and-white ball: its green panels are not the carpet's green. With carpet_by_colour
    // they count as ball (non-green test) and their border with the carpet as its border; off,
    // the ball is half "green" and fails the non-green test.
    void greenPanelledBall()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 130, 200, kWhite);
        const int r = int(std::lround(expectedRadius(c, 130)));
        // Green wedges over half the ball, reaching its border.
        for (int k = 0; k < 4; ++k)
            cv::ellipse(frame, p, cv::Size(r, r), 0, 90.0 * k, 90.0 * k + 45.0, kPanelGreen, cv::FILLED);
        const BallCandidate on = validateFrame(c, frame, p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
        QVERIFY2(on.scores.nonGreenPct > 95, qPrintable(verdict(on)));
        c.validation.carpetByColour = false;
        const BallCandidate off = validateFrame(c, frame, p);
        QVERIFY2(off.rejected == RejectReason::NonGreen, qPrintable(verdict(off)));
    }

    // Green panels of the carpet's own hue and saturation, told apart only by brightness (the
    // optics renderer's green-and-white ball): validation.carpet_value_tolerance judges it.
    void darkGreenPanelsNeedTheValueTolerance()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 130, 200, kWhite);
        const int r = int(std::lround(expectedRadius(c, 130)));
        for (int k = 0; k < 4; ++k)
            cv::ellipse(frame, p, cv::Size(r, r), 0, 90.0 * k, 90.0 * k + 45.0, kGreen * 0.5, cv::FILLED);
        QCOMPARE(validateFrame(c, frame, p).rejected, RejectReason::NonGreen);
        c.validation.carpetTolerance.value = 30;
        const BallCandidate on = validateFrame(c, frame, p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
    }

    // Green of the carpet's hue and saturation but darker than the carpet beside it (a ball's
    // shaded side, a green-and-white ball's panels at its silhouette) is ball in the non-green
    // test's square (validation.square_shade_tolerance); off, the thesis' colour alone. A round
    // shadow on the carpet, and a robot's black edge beside shaded carpet, stay green.
    void shadedGreenIsBallInTheSquare()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 130, 200, kWhite);
        const int r = int(std::lround(expectedRadius(c, 130)));
        const cv::Scalar shaded = kGreen * 0.75;  // V 105 against the carpet's 140
        // Its far half shaded: open to the carpet, so not an enclosed green panel.
        cv::ellipse(frame, p, cv::Size(r, r), 0, 90.0, 270.0, shaded, cv::FILLED);
        const BallCandidate on = validateFrame(c, frame, p);
        QVERIFY2(on.scores.nonGreenPct >= c.validation.minNonGreenPct, qPrintable(verdict(on)));
        c.validation.squareShadeTolerance = 0;
        const BallCandidate off = validateFrame(c, frame, p);
        QVERIFY2(off.rejected == RejectReason::NonGreen, qPrintable(verdict(off)));
        // 40 V darker than the carpet is not darker than a tolerance of 50.
        c.validation.squareShadeTolerance = 50;
        QCOMPARE(validateFrame(c, frame, p).rejected, RejectReason::NonGreen);

        c.validation.squareShadeTolerance = 20;
        cv::Mat shadow = greenField(c);
        const cv::Point q = drawBall(shadow, c, 130, 200, shaded);
        const BallCandidate round = validateFrame(c, shadow, q);
        QVERIFY2(round.rejected == RejectReason::NonGreen, qPrintable(verdict(round)));
        // Half the square a robot's black, half shaded carpet: nothing of a ball's own colours.
        cv::Mat edge = greenField(c);
        cv::circle(edge, q, 4 * r, shaded, cv::FILLED);
        cv::rectangle(edge, cv::Point(q.x - 4 * r, q.y - 4 * r), cv::Point(q.x, q.y + 4 * r), kBlack, cv::FILLED);
        const BallCandidate robot = validateFrame(c, edge, q);
        QVERIFY2(robot.rejected == RejectReason::NonGreen, qPrintable(verdict(robot)));
    }

    // Carpet by colour still sees carpet as carpet: noisy, vignetted carpet with a green speck
    // is rejected as before, and a disc of the carpet's own green (a lighter patch) is no ball.
    void carpetByColourKeepsCarpetGreen()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 140, 120, cv::Scalar(50, 165, 50));
        blurAndNoise(frame, 1, 6.0);
        const BallCandidate cand = validateFrame(c, frame, p);
        QVERIFY2(cand.rejected == RejectReason::NonGreen, qPrintable(verdict(cand)));
    }

    // A known ball colour: an orange ball half of whose square reads as carpet-green (a panel
    // of the carpet's own green) fails the non-green test, unless the team says it is orange.
    void ballHintPassesTheColourTests()
    {
        Config c;
        // The green half stops 2 px inside the border; at the default 1 px green-panel margin its
        // walks would reach that orange rim and make it an enclosed panel of the ball, whose rays
        // then end on no border into carpet. This test is about the hint, not the panels.
        c.validation.greenPanelMarginPx = 2.0;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 130, 300);
        const int r = int(std::lround(expectedRadius(c, 130)));
        cv::ellipse(frame, p, cv::Size(r - 2, r - 2), 0, 0, 180, kGreen, cv::FILLED);
        const BallCandidate none = validateFrame(c, frame, p);
        QVERIFY2(none.rejected == RejectReason::NonGreen, qPrintable(verdict(none)));
        c.validation.ballHint = "orange";
        const BallCandidate orange = validateFrame(c, frame, p);
        QVERIFY2(orange.rejected == RejectReason::None, qPrintable(verdict(orange)));
        QVERIFY(orange.scores.hintPct >= c.validation.ballHintMinPct);
        // A hint of another colour changes nothing.
        c.validation.ballHint = "cyan";
        QCOMPARE(validateFrame(c, frame, p).rejected, RejectReason::NonGreen);
    }

    // The real-frame false positives. A round white floor reflection: a soft-edged whitish disc
    // of the ball's size on the carpet. A rod tip: the end of a support rod that sticks out of
    // its mask, grey, with a rounded end.
    void realFrameFalsePositives_data()
    {
        QTest::addColumn<int>("scene");
        QTest::newRow("floor reflection") << 0;
        QTest::newRow("rod tip") << 1;
    }
    void realFrameFalsePositives()
    {
        QFETCH(int, scene);
        Config c;
        cv::Mat frame = greenField(c);
        const double distance = 140;
        const cv::Point2d q = pointAt(c, distance, 250);
        const cv::Point p(int(std::lround(q.x)), int(std::lround(q.y)));
        const int r = int(std::lround(expectedRadius(c, distance)));
        if (scene == 0) {
            cv::Mat light(frame.size(), CV_8UC3, cv::Scalar(0, 0, 0));
            cv::circle(light, p, r, cv::Scalar(190, 120, 190), cv::FILLED);
            cv::GaussianBlur(light, light, cv::Size(0, 0), 2.5);
            frame += light;
        } else {
            // The rod runs from the mirror rim inwards and ends at p; its mask stops r px short.
            const cv::Scalar rod(110, 110, 110);
            const cv::Point out = cv::Point(int(std::lround(pointAt(c, 260, 250).x)), int(std::lround(pointAt(c, 260, 250).y)));
            cv::line(frame, p, out, rod, 2 * r);
            cv::circle(frame, p, r, rod, cv::FILLED);
            c.mask = cv::Mat(frame.size(), CV_8UC1, cv::Scalar(255));
            const cv::Point2d dir = (cv::Point2d(out) - cv::Point2d(p)) / cv::norm(cv::Point2d(out) - cv::Point2d(p));
            const cv::Point maskStart(int(std::lround(p.x + dir.x * r)), int(std::lround(p.y + dir.y * r)));
            cv::line(c.mask, maskStart, out, cv::Scalar(0), 2 * r + 6);
        }
        blurAndNoise(frame, 1, 3.0);
        const BallCandidate cand = validateFrame(c, frame, p);
        qInfo().noquote() << verdict(cand);
        // A rod as wide as the ball whose visible end is round is, on its visible half, a ball
        // half behind the rod: shape and colour classes cannot tell them apart (the grey rod is
        // "unknown" like a blue ball). What would: a mask drawn past the rod's end, or the ball
        // colour hint required of partly masked candidates.
        if (scene == 1) QEXPECT_FAIL("rod tip", "a ball-wide rod end is a half-hidden ball to every test", Continue);
        QVERIFY2(cand.rejected != RejectReason::None, qPrintable(verdict(cand)));
    }

    // validation.refuse_at_rim: a circle that reaches past the outer radius (less the margin) is
    // refused, however ball-like its inner part; one that ends inside is judged as usual; off,
    // the cut circle is judged on its inner part and passes.
    void refusedAtTheRim()
    {
        Config c;
        c.geometry.outerRadius = 180;  // a smaller mirror: the far ball is large enough to judge
        c.validation.rimMarginPx = 1.0;
        const double outer = c.geometry.outerRadius;
        const double cut = outer - 0.5 * expectedRadius(c, outer);  // its outer rim beyond the outer radius
        const double inside = outer - expectedRadius(c, outer) - c.validation.rimMarginPx - 2.0;
        for (double distance : {cut, inside}) {
            cv::Mat frame = greenField(c);
            const cv::Point p = drawBall(frame, c, distance, 0);
            const BallCandidate on = validateFrame(c, frame, p);
            Config off = c;
            off.validation.refuseAtRim = false;
            const BallCandidate judged = validateFrame(off, frame, p);
            QVERIFY2(judged.rejected == RejectReason::None, qPrintable(QString::number(distance) + ": " + verdict(judged)));
            if (distance == cut)
                QVERIFY2(on.rejected == RejectReason::OutsideArea, qPrintable(verdict(on)));
            else
                QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
        }
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

    // A white ball with panels of the carpet's own green (the optics renderer's green-and-white
    // ball): colour cannot tell them from the carpet, their place inside the ball's white can
    // (validation.green_panels). Off, the ball is "green" and fails the non-green test; with too
    // little white of its own (green_panel_min_own_pct) the panels do not count either.
    void carpetGreenPanelsInsideTheWhite()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point p = drawBall(frame, c, 110, 200, kWhite);
        const double r = expectedRadius(c, 110);
        cv::circle(frame, p, int(std::lround(r / 3)), kGreen, cv::FILLED);
        for (int k = 0; k < 4; ++k) {
            const double a = (90.0 * k + 45.0) * M_PI / 180.0;
            const cv::Point q(int(std::lround(p.x + 0.55 * r * std::cos(a))), int(std::lround(p.y + 0.55 * r * std::sin(a))));
            cv::circle(frame, q, int(std::lround(r / 5)), kGreen, cv::FILLED);
        }
        const BallCandidate on = validateFrame(c, frame, p);
        QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
        QVERIFY2(on.scores.nonGreenPct > 95, qPrintable(verdict(on)));
        Config off = c;
        off.validation.greenPanels = false;
        const BallCandidate thesis = validateFrame(off, frame, p);
        QVERIFY2(thesis.rejected == RejectReason::NonGreen, qPrintable(verdict(thesis)));
        Config guarded = c;
        guarded.validation.greenPanelMinOwnPct = 99;
        QCOMPARE(validateFrame(guarded, frame, p).rejected, RejectReason::NonGreen);
    }

    // Carpet between two white lines crossing is bounded by white on five of eight sides, like a
    // green panel at a ball's silhouette: it stays carpet at the default green_panel_min_directions
    // (6) and counts as a panel at 5, which is why the default is 6.
    void lineCrossingCarpetIsNoPanel()
    {
        Config c;
        cv::Mat frame = greenField(c);
        const cv::Point2d pd = pointAt(c, 150, 120);
        const cv::Point p(int(std::lround(pd.x)), int(std::lround(pd.y)));
        cv::line(frame, p - cv::Point(40, 0), p + cv::Point(40, 0), kWhite, 3);
        cv::line(frame, p - cv::Point(0, 40), p + cv::Point(0, 40), kWhite, 3);
        const BallCandidate dflt = validateFrame(c, frame, p);
        QVERIFY2(dflt.scores.nonGreenPct < c.validation.minNonGreenPct, qPrintable(verdict(dflt)));
        QCOMPARE(dflt.rejected, RejectReason::NonGreen);
        Config five = c;
        five.validation.greenPanelMinDirections = 5;
        const BallCandidate loose = validateFrame(five, frame, p);
        QVERIFY2(loose.scores.nonGreenPct > dflt.scores.nonGreenPct, qPrintable(verdict(loose)));
    }

    // A green panel near the silhouette, with only a thin rim of the ball's white beyond it
    // (1.5 px here): the walk outwards must reach that rim. The default margin (1 px) does; the
    // earlier 2 px stopped the walk short and called the panel carpet (optics matrix, seeds 1-4:
    // +15 balls combined, +12 specific, no false-positive frame more for either).
    void panelWithAThinWhiteRimIsEnclosed()
    {
        struct Rim : PanelPixels {
            bool known(cv::Point p) const override { return std::hypot(p.x, p.y) <= 20; }
            // White from 8.5 px to the border at 10; field (panel, then carpet) elsewhere.
            bool field(cv::Point p) const override
            {
                const double d = std::hypot(p.x, p.y);
                return d < 8.5 || d > 10.0;
            }
        } pixels;
        const BallDisc disc{0, 0, 10};
        const double margin = ValidationOptions{}.greenPanelMarginPx;
        QVERIFY(onEnclosedPanel({6, 0}, disc, margin, pixels));
        QVERIFY(onEnclosedPanel({0, -6}, disc, margin, pixels));
        QVERIFY(!onEnclosedPanel({6, 0}, disc, 2.0, pixels));
        // The carpet beyond the border is never a panel, whatever the margin.
        QVERIFY(!onEnclosedPanel({12, 0}, disc, margin, pixels));
    }
};

QTEST_GUILESS_MAIN(ValidationTest)
#include "core_validation_test.moc"
