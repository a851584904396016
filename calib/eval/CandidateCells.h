#pragma once
// A candidate's place and validation scores as cells of a markdown row, so that the false-positive
// and the missed-ball listings (omnitune-eval --false-positives, --miss-list) read alike.
#include "core/BallCandidate.h"

#include <string>

namespace omnitune {

// The header cells that candidateCells() fills, "| at (x, y) | r exp | ... |" without the
// leading "|" of the first cell's left border.
std::string candidateCellsHeader();
// The separator row's cells for candidateCellsHeader().
std::string candidateCellsRule();
// "(x, y) | r exp | dist | search | reason | non-green | non-black | circ | spread | run-on | fit r (dx, dy) |".
std::string candidateCells(const BallCandidate& c);
// The same number of empty cells.
std::string emptyCandidateCells();

}  // namespace omnitune
