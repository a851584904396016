#include "calib/eval/CandidateCells.h"

#include <cstdio>

namespace omnitune {

namespace {
constexpr int kCells = 11;
}

std::string candidateCellsHeader()
{
    return " at (x, y) | r exp | dist | search | verdict | non-green | non-black | circ | spread | run-on | fit r (dx, dy) |";
}

std::string candidateCellsRule()
{
    std::string s;
    for (int i = 0; i < kCells; ++i) s += "---|";
    return s;
}

std::string candidateCells(const BallCandidate& c)
{
    const ValidationScores& s = c.scores;
    const std::string verdict(rejectReasonName(c.rejected));
    char line[512];
    std::snprintf(line, sizeof line, " (%d, %d) | %.1f | %.0f | %s | %s | %.0f | %.0f | %.0f | %.2f | %.0f | %.1f (%.1f, %.1f) |",
                  c.x, c.y, c.expectedRadiusPx, c.distancePx, std::string(candidateSourceName(c.source)).c_str(),
                  verdict.c_str(), s.nonGreenPct, s.nonBlackPct, s.circularityPct, s.borderSpreadPx, s.runOnPct,
                  s.fitRadiusPx, s.fitDx, s.fitDy);
    return line;
}

std::string emptyCandidateCells()
{
    std::string s;
    for (int i = 0; i < kCells; ++i) s += " |";
    return s;
}

}  // namespace omnitune
