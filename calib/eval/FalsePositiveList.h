#pragma once
// omnitune-eval --false-positives: every false-positive frame of a quality run, one row each
// (cell, frame, what was detected and its validation scores), and optionally the pixels around
// each, enlarged, as PNGs to look at one by one (issue 9: tell each false positive from a ball).
#include "calib/eval/QualityRun.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

// A markdown table of the false positives of `variants`, in matrix order.
std::string falsePositiveListMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants);

// Writes each false positive's crop, enlarged `scale` times with the detected circle (red) and the
// ball's true circle (green, when it lies in the crop) drawn, to `folder` (created when missing)
// as "<variant>_<cell>_f<frame>.png". Returns an error naming the file that failed, or nothing.
std::optional<std::string> writeFalsePositiveCrops(const QualityRun& run, const std::vector<std::size_t>& variants,
                                                   const std::string& folder, int scale = 8);

}  // namespace omnitune
