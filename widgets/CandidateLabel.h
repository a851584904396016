#pragma once
// The overlay's short label of a candidate ("A3 98/100/96": radial area 3, then its non-green,
// non-black and circularity scores in %) and the long explanation the pane's tooltip and the
// legend give for it, so that the notation is explained where it is seen.
#include "core/BallCandidate.h"
#include "core/Validation.h"

#include <QString>

namespace omnitune {

QString candidateLabel(const BallCandidate& candidate);
// One candidate in words, with the thresholds it was judged against (rich text).
QString candidateExplanation(const BallCandidate& candidate, const ValidationOptions& thresholds);
// How to read a label, for the legend (rich text).
QString candidateLabelLegend();

}  // namespace omnitune
