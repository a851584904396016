// The candidate prefilter (core/CandidatePrefilter.h): maxima that validation would refuse on
// their square's colour take no candidate slot, so a ball's weaker maximum in the same radial
// area still becomes a candidate.
#include "DrawnScene.h"
#include "core/CandidatePrefilter.h"
#include "core/Pipeline.h"
#include "core/SpecificHough.h"

#include <QtTest>

using namespace omnitune;
using namespace omnitune::test;

namespace {

bool near(double x, double y, cv::Point p, double tol = 2.0) { return std::hypot(x - p.x, y - p.y) <= tol; }

// Two slots per area; the ball at 158 px (area 140..170) and two decoys in the same area at
// 145 px, inside near_robot_radius so their votes count twice: each out-votes the ball.
Config twoSlots()
{
    Config c;
    c.algorithm = Algorithm::Specific;
    c.hough.nearRobotRadius = 150;
    c.hough.maximaPerArea = 2;
    c.hough.blobSeeds = false;  // the maxima alone
    return c;
}

Config prefilterOff(Config c)
{
    c.hough.prefilterNonGreen = 0;
    c.hough.prefilterNonBlack = 0;
    c.hough.prefilterRim = false;
    return c;
}

// A line crossing's stand-in: a thin white ring of the ball's size around a white dot, so the
// centre is non-green (it gets votes) but its square is mostly carpet.
void drawRing(cv::Mat& frame, const Config& c, double distance, double angleDeg)
{
    const cv::Point2d p = pointAt(c, distance, angleDeg);
    const cv::Point centre(int(std::lround(p.x)), int(std::lround(p.y)));
    cv::circle(frame, centre, int(std::lround(expectedRadius(c, distance))), kWhite, 1, cv::LINE_8);
    cv::circle(frame, centre, 1, kWhite, cv::FILLED, cv::LINE_8);
}

bool candidateAt(const Config& c, const cv::Mat& frame, cv::Point ball, int* prefiltered = nullptr)
{
    const EdgeStages s(c, frame);
    SpecificHough hough(c.hough, s.geometry, s.ball, candidatePrefilterFor(c));
    std::vector<BallCandidate> cands;
    hough.process(s.edges, s.binary, cands, s.classes);
    if (prefiltered) *prefiltered = hough.stats().prefiltered;
    for (const auto& k : cands)
        if (near(k.x, k.y, ball, 3.0)) return true;
    return false;
}

// Whether the whole pipeline detects the ball at `ball`.
bool pipelineFindsBall(const Config& c, const cv::Mat& frame, cv::Point ball)
{
    PipelineResult r;
    Pipeline(c).process(frame, PixelFormat::Bgr8, r);
    return r.detection.found && near(r.detection.px, r.detection.py, ball);
}

}  // namespace

class CandidatePrefilterTest : public QObject {
    Q_OBJECT
private slots:
    void mostlyGreenMaximaGiveWay()
    {
        const Config c = twoSlots();
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 158, 30);
        drawRing(frame, c, 145, 200);
        drawRing(frame, c, 145, 260);
        // Without the prefilter the two rings take the area's slots (the scene is the failure).
        QVERIFY(!candidateAt(prefilterOff(c), frame, ball));
        int dropped = 0;
        QVERIFY(candidateAt(c, frame, ball, &dropped));
        QVERIFY(dropped >= 2);
        // And the pipeline finds it.
        QVERIFY(pipelineFindsBall(c, frame, ball));
    }

    void blackMaximaGiveWay()
    {
        Config c = twoSlots();
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 158, 30);
        drawBall(frame, c, 145, 200, kBlack);
        drawBall(frame, c, 145, 260, kBlack);
        Config greenOnly = prefilterOff(c);
        greenOnly.hough.prefilterNonGreen = c.hough.prefilterNonGreen;
        QVERIFY(!candidateAt(greenOnly, frame, ball));  // black discs are non-green: only non-black tells
        QVERIFY(candidateAt(c, frame, ball));
    }

    // In a vignetted corner a dark ball falls below the frame's black (0.45 x the frame's carpet
    // V) but not below the carpet around it: validation counts it non-black there
    // (black_by_local_carpet), so the prefilter must not refuse it on the class share.
    void aDarkBallInADimCornerKeepsItsSlot()
    {
        const Config c = twoSlots();
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 158, 30, cv::Scalar(84, 84, 84));
        const int half = int(std::ceil(4.0 * expectedRadius(c, 158)));
        cv::Mat corner = frame(cv::Rect(ball.x - half, ball.y - half, 2 * half + 1, 2 * half + 1));
        corner.convertTo(corner, -1, 0.6);  // carpet V 84 (field), ball V 50 (black by the frame's 63)
        const FrameColour colour(frame, PixelFormat::Bgr8);
        {
            const EdgeStages s(c, frame);
            QVERIFY(ColourRoles(c.colors.classes).black(s.classes.at<std::uint8_t>(ball)));
            QVERIFY(ColourRoles(c.colors.classes).field(s.classes.at<std::uint8_t>(ball.y, ball.x + 2 * half / 3)));
        }
        auto candidate = [&](const Config& k, const FrameColour* col) {
            const EdgeStages s(k, frame);
            SpecificHough hough(k.hough, s.geometry, s.ball, candidatePrefilterFor(k));
            std::vector<BallCandidate> cands;
            hough.process(s.edges, s.binary, cands, s.classes, col);
            for (const auto& q : cands)
                if (near(q.x, q.y, ball, 3.0) && q.rejected == RejectReason::None) return true;
            return false;
        };
        QVERIFY(candidate(c, &colour));
        QVERIFY(!candidate(c, nullptr));  // the class share alone refuses it
        Config byClass = c;
        byClass.validation.blackByLocalCarpet = false;
        QVERIFY(!candidate(byClass, &colour));
        // And validation agrees: the pipeline finds it.
        QVERIFY(pipelineFindsBall(c, frame, ball));
    }

    // A ball touching a robot's black body is one non-green region with it: too large for a
    // blob seed unless the black classes are left out of the flood.
    void aBallBesideARobotStillSeeds()
    {
        Config c;
        c.hough.maximaPerArea = 1;  // no maxima beyond the thesis' one per area: the seed must do it
        c.hough.minAccumulator = 100000;  // and no maximum at all
        c.hough.seedsWithoutBlack = true;
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 150, 40);
        const double r = expectedRadius(c, 150);
        cv::rectangle(frame, cv::Point(ball.x + int(r) - 1, ball.y - 3 * int(r)),
                      cv::Point(ball.x + 5 * int(r), ball.y + 3 * int(r)), kBlack, cv::FILLED);
        auto seeded = [&](const Config& k) {
            const EdgeStages s(k, frame);
            SpecificHough hough(k.hough, s.geometry, s.ball, candidatePrefilterFor(k));
            std::vector<BallCandidate> cands;
            hough.process(s.edges, s.binary, cands, s.classes);
            for (const auto& q : cands)
                if (q.source == CandidateSource::BlobSeed && near(q.x, q.y, ball, 2.0)) return true;
            return false;
        };
        Config merged = c;
        merged.hough.seedsWithoutBlack = false;
        QVERIFY(!seeded(merged));
        QVERIFY(seeded(c));
    }

    // A known ball colour skips validation's colour tests, so the prefilter skips them too.
    void aBallHintTurnsTheColourTestsOff()
    {
        Config c;
        QVERIFY(candidatePrefilterFor(c).minNonGreenPct > 0);
        QVERIFY(candidatePrefilterFor(c).minNonBlackPct > 0);
        c.validation.ballHint = "orange";
        QCOMPARE(candidatePrefilterFor(c).minNonGreenPct, 0.0);
        QCOMPARE(candidatePrefilterFor(c).minNonBlackPct, 0.0);
        c.validation.refuseAtRim = false;
        QVERIFY(!candidatePrefilterFor(c).active());
    }

    // A listed refusal gives the reason validation would: "too small" for a small ball refused
    // on colour, but "outside area" for one the rim refuses (validation checks the rim first).
    void aRimRefusalKeepsItsReason()
    {
        Config c;
        c.algorithm = Algorithm::Specific;
        c.hough.blobSeeds = false;
        c.validation.rimTest = false;
        c.validation.rimMarginPx = 8;  // the prefilter's reach ends 8 px inside the rim
        const double d = c.geometry.outerRadius - 10;
        QVERIFY(d + expectedRadius(c, d) > c.geometry.outerRadius - c.validation.rimMarginPx);
        c.validation.minRadiusPx = expectedRadius(c, d) + 1;  // and too small for validation
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, d, 30);
        const EdgeStages s(c, frame);
        SpecificHough hough(c.hough, s.geometry, s.ball, candidatePrefilterFor(c));
        std::vector<BallCandidate> cands;
        hough.process(s.edges, s.binary, cands, s.classes);
        QVERIFY(hough.stats().prefilterListed > 0);
        bool listed = false;
        for (const auto& k : cands) {
            if (!near(k.x, k.y, ball, 3.0)) continue;
            QCOMPARE(k.rejected, RejectReason::OutsideArea);
            listed = true;
        }
        QVERIFY(listed);
    }

    // Maxima refused at the rim give way too: two whole discs whose circles reach past the
    // prefilter's reach (cut by the rim, as validation would refuse them) out-vote a ball in the
    // same radial area whose border merges on its outer side with a robot's black body; with the
    // rim prefilter they take no slot and the ball keeps one. The colour prefilter is off in both
    // runs: the decoys pass it (they are the ball's colour), so only the rim can free the slots.
    void rimMaximaGiveWay()
    {
        Config c = twoSlots();
        c.ball.c0 = 8.0;  // one radius everywhere: every disc's full circle votes alike
        c.ball.c1 = 0.0;
        c.ball.c2 = 0.0;
        c.hough.prefilterNonGreen = 0;
        c.hough.prefilterNonBlack = 0;
        c.validation.rimTest = false;
        c.validation.rimMarginPx = 8;  // the reach ends at 232 px
        const double ballAt = 212, decoyAt = 229;  // both in the area 205..240
        QVERIFY(decoyAt + 8 > c.geometry.outerRadius - c.validation.rimMarginPx);
        QVERIFY(decoyAt + 8 < c.geometry.outerRadius);  // but whole in the image's ring
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, ballAt, 30);
        // A robot's body the ball touches: ball and body are one non-green blob, so the ball's
        // border there has no edge and its maximum is weaker than a whole disc's.
        // The body: an 8 px thick bar across the ball's outward direction, centred 2 px past its
        // border (so it covers the border), 84 px long.
        const cv::Point2d outward = (pointAt(c, ballAt + 14, 30) - pointAt(c, ballAt, 30)) / 14.0;
        const cv::Point2d across(-outward.y, outward.x);
        const cv::Point2d bodyAt = pointAt(c, ballAt + 8 + 2, 30);
        cv::line(frame, bodyAt + across * 42, bodyAt - across * 42, kBlack, 8);
        drawBall(frame, c, decoyAt, 200);
        drawBall(frame, c, decoyAt, 260);
        Config rimOff = c;
        rimOff.hough.prefilterRim = false;
        int dropped = 0;
        QVERIFY(!candidateAt(rimOff, frame, ball, &dropped));  // the decoys take both slots
        QCOMPARE(dropped, 0);
        QVERIFY(candidateAt(c, frame, ball, &dropped));
        QVERIFY(dropped >= 2);
        // And the pipeline finds it.
        QVERIFY(pipelineFindsBall(c, frame, ball));
    }

    // The robot lists only the strongest refusals per area; the miss diagnosis
    // (Pipeline::setListEveryRefusal) lists every one, after those, without changing a verdict:
    // otherwise a ball refused behind the cap reads as "no candidate".
    void everyRefusalIsListedWhenAsked()
    {
        const Config c = twoSlots();
        cv::Mat frame = greenField(c);
        const cv::Point ball = drawBall(frame, c, 158, 30);
        std::vector<cv::Point> decoys;
        for (double angle : {110.0, 170.0, 230.0, 290.0}) decoys.push_back(drawBall(frame, c, 145, angle, kBlack));
        auto refusedAt = [&](const PipelineResult& r, cv::Point p) {
            for (const auto& k : r.candidates)
                if (near(k.x, k.y, p, 3.0) && k.rejected == RejectReason::NonBlack) return true;
            return false;
        };
        Pipeline robot(c);
        Pipeline explaining(c);
        explaining.setListEveryRefusal(true);
        explaining.setConfig(c);  // the setting outlives a new config
        PipelineResult fast;
        PipelineResult full;
        robot.process(frame, PixelFormat::Bgr8, fast);
        explaining.process(frame, PixelFormat::Bgr8, full);
        QVERIFY(fast.detection.found);
        QVERIFY(near(fast.detection.px, fast.detection.py, ball));
        QCOMPARE(full.detection.px, fast.detection.px);
        QCOMPARE(full.detection.py, fast.detection.py);
        QCOMPARE(fast.hough.prefilterUnlisted, 0);
        QVERIFY(fast.hough.prefilterListed > 0);
        int listedByRobot = 0;
        for (const cv::Point& d : decoys) {
            listedByRobot += refusedAt(fast, d);
            QVERIFY(refusedAt(full, d));
        }
        QVERIFY(listedByRobot < int(decoys.size()));
        QCOMPARE(full.hough.prefilterListed, fast.hough.prefilterListed);
        QCOMPARE(full.hough.prefilterUnlisted, int(decoys.size()) - listedByRobot);
        // The unlisted come last.
        const std::size_t unlistedFrom = full.candidates.size() - std::size_t(full.hough.prefilterUnlisted);
        for (std::size_t i = unlistedFrom; i < full.candidates.size(); ++i)
            QCOMPARE(full.candidates[i].rejected, RejectReason::NonBlack);
    }

    // The shares count processed pixels only, by colour class.
    void squareSharesCountProcessedPixels()
    {
        const Config c;
        const ColourRoles roles(c.colors.classes);
        cv::Mat binary(9, 9, CV_8UC1, cv::Scalar(255));  // all green
        cv::Mat classes(9, 9, CV_8UC1, cv::Scalar(0));
        cv::Mat used(9, 9, CV_8UC1, cv::Scalar(255));
        binary(cv::Rect(3, 3, 3, 3)).setTo(0);  // 9 non-green of the 5x5 square's 25
        used.row(2).setTo(0);                    // one row of 5 not processed: 20 left
        SquareShares s = classSquareShares(binary, classes, used, roles, 4, 4, 5);
        QCOMPARE(s.nonGreenPct, 100.0 * 9 / 20);
        QCOMPARE(s.nonBlackPct, 100.0);  // class 0 is no black class
        used.setTo(0);
        s = classSquareShares(binary, classes, used, roles, 4, 4, 5);
        QCOMPARE(s.nonGreenPct, 0.0);
    }
};

QTEST_APPLESS_MAIN(CandidatePrefilterTest)
#include "core_candidate_search_prefilter_test.moc"
