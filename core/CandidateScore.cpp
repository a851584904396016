#include "core/CandidateScore.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

namespace {

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

// Votes of a drawn ball's 3x3 sum per px of expected radius: ~17 (its border has ~5.7 r edge
// pixels, each locus crosses ~3 pixels of the 3x3 window); near the robot votes count twice,
// so the support saturates there early, which is harmless (every term is capped at 1).
constexpr double kVotesPerRadiusPx = 16.0;

}  // namespace

double candidateScore(const BallCandidate& c)
{
    const ValidationScores& s = c.scores;
    const double r = std::max(1.0, c.expectedRadiusPx);
    const double circularity = clamp01(s.circularityPct / 100.0);
    const double nonGreen = clamp01(s.nonGreenPct / 100.0);
    const double nonBlack = clamp01(s.nonBlackPct / 100.0);
    const double stays = 1.0 - clamp01(s.runOnPct / 100.0);
    // A ball's border lies within ~0.5 px of one radius; a corner's or a robot's wanders.
    const double tight = 1.0 / (1.0 + s.borderSpreadPx / (0.5 + 0.1 * r));
    double support;
    if (c.source == CandidateSource::OpenCvHough)
        support = 1.0 - clamp01(std::abs(c.radiusPx - c.expectedRadiusPx) / r);
    else
        support = clamp01(c.accumulator / (kVotesPerRadiusPx * r));
    // Circularity says most about the shape; the colour shares are mostly saturated for every
    // candidate that passed the thresholds, so they weigh less.
    return 0.35 * circularity + 0.10 * nonGreen + 0.10 * nonBlack + 0.15 * stays + 0.15 * tight + 0.15 * support;
}

bool preferCandidate(const BallCandidate& a, const BallCandidate& b, bool byScore)
{
    if (byScore) return a.score > b.score;
    if (a.scores.circularityPct != b.scores.circularityPct) return a.scores.circularityPct > b.scores.circularityPct;
    return a.accumulator > b.accumulator;
}

}  // namespace omnitune
