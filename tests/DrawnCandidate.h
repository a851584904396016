#pragma once
// Validating a candidate at the centre of a drawn test scene (DrawnScene.h), for the core tests
// of one validation rule at a time: the verdict as readable text, and a ray walked pixel by
// pixel as traceBorder walks it.
#include "DrawnScene.h"
#include "core/FrameColour.h"
#include "core/Validation.h"

#include <QString>
#include <QtTest>

#include <cmath>
#include <string>

namespace omnitune::test {

// The verdict and every score, for a failure message.
inline QString verdict(const BallCandidate& c)
{
    return QString("rejected by %1 (scores %2 / %3 / circularity %4, run-on %5, fit r %6 of %7 expected at %8 px, fit "
                   "centre off by (%9))")
        .arg(QString::fromStdString(std::string(rejectReasonName(c.rejected))))
        .arg(c.scores.nonGreenPct)
        .arg(c.scores.nonBlackPct)
        .arg(c.scores.circularityPct)
        .arg(c.scores.runOnPct)
        .arg(c.scores.fitRadiusPx)
        .arg(c.expectedRadiusPx)
        .arg(c.distancePx)
        .arg(QString("%1, %2").arg(c.scores.fitDx).arg(c.scores.fitDy));
}

// A candidate centred on `p` of `frame`, validated under `c` with the frame's colours (carpet by
// colour, black against the local carpet).
inline BallCandidate validateAt(const Config& c, const cv::Mat& frame, cv::Point p)
{
    const EdgeStages s(c, frame);
    BallCandidate cand;
    cand.x = p.x;
    cand.y = p.y;
    cand.distancePx = s.geometry.distanceAt(p.x, p.y);
    cand.expectedRadiusPx = s.ball.radiusAt(cand.distancePx);
    const FrameColour colour(frame, PixelFormat::Bgr8);
    validateCandidate(cand, s.classes, s.edges, s.geometry, s.ball, c.validation, &colour);
    return cand;
}

// The colour class id the front end gives pixel `p` of `frame` under `c` (0: no class).
inline int classAt(const Config& c, const cv::Mat& frame, cv::Point p)
{
    return int(EdgeStages(c, frame).classes.at<std::uint8_t>(p));
}

// The candidate at the centre of what `draw(frame, centre, expectedRadius)` drew `distance` px
// from the robot centre at `angleDeg`, validated under `c` with its own colour roles.
template <class Draw>
BallCandidate validateDrawn(const Config& c, double distance, double angleDeg, Draw draw)
{
    cv::Mat frame = greenField(c);
    const cv::Point2d p = pointAt(c, distance, angleDeg);
    const cv::Point centre(int(std::lround(p.x)), int(std::lround(p.y)));
    draw(frame, centre, expectedRadius(c, distance));
    const EdgeStages s(c, frame);
    BallCandidate cand;
    cand.x = centre.x;
    cand.y = centre.y;
    cand.distancePx = s.geometry.distanceAt(centre.x, centre.y);
    cand.expectedRadiusPx = s.ball.radiusAt(cand.distancePx);
    validateCandidate(cand, s.classes, s.edges, s.geometry, s.ball, c.validation, nullptr, ColourRoles(c.colors.classes));
    return cand;
}

// A validation switch's own test: with `rule` on (as `c` has it) the drawn ball is accepted; with
// it off it fails circularity, on a lower score. QVERIFY-style: returns early on a failure.
template <class Draw>
void checkRuleAcceptsIt(Config c, bool ValidationOptions::*rule, double distance, double angleDeg, Draw draw)
{
    const BallCandidate on = validateDrawn(c, distance, angleDeg, draw);
    QVERIFY2(on.rejected == RejectReason::None, qPrintable(verdict(on)));
    c.validation.*rule = false;
    const BallCandidate off = validateDrawn(c, distance, angleDeg, draw);
    QVERIFY2(off.rejected == RejectReason::Circularity, qPrintable(verdict(off)));
    QVERIFY(off.scores.circularityPct < on.scores.circularityPct);
}

// The class id of the first colour class with `role` (0, no class, when none has it): what a
// class-image scene paints for the carpet, a line or the ball.
inline std::uint8_t roleClassId(const ColourClasses& classes, ColourRole role)
{
    for (std::size_t i = 0; i < classes.size(); ++i)
        if (classes[i].role == role) return std::uint8_t(colourClassId(int(i)));
    return 0;
}

// Walks a ray from (x, y) along +x out to `reach` px in half-pixel steps, each pixel once, as the
// circularity test does; true as soon as `step(pixel, r)` is.
template <class Step>
bool walkRayAlongX(int x, int y, double reach, Step step)
{
    cv::Point last(-1, -1);
    for (double r = 0.5; r <= reach; r += 0.5) {
        const cv::Point q(int(std::lround(x + r)), y);
        if (q == last) continue;
        last = q;
        if (step(q, r)) return true;
    }
    return false;
}

}  // namespace omnitune::test
