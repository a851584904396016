#pragma once
// Which of a result's candidates are the specific search's prefilter refusals (hough.prefilter_*):
// listed after its own candidates, rejected with the prefilter's reason and never validated, so
// their scores are the colour-class shares of the square at the Hough maximum, not validation's.
// The window's candidate table and the evaluation's miss list both say so.
#include "core/PipelineResult.h"

#include <vector>

namespace omnitune {

// One flag per candidate of `result`, true for a prefilter refusal. The refusals (listed and,
// with Pipeline::setListEveryRefusal, unlisted) are the last specific-search candidates; OpenCV's
// circles, appended after them, are never prefiltered.
std::vector<bool> prefilterRefusals(const PipelineResult& result);

}  // namespace omnitune
