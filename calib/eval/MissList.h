#pragma once
// omnitune-eval --miss-list: every missed ball frame of a quality run, one row each (cell, frame,
// the ball's truth, why it was missed, the candidate at the ball that got farthest through
// validation and what was detected instead), and optionally the pixels around each ball,
// enlarged, as PNGs (issue 9: look at the misses one by one before attacking a cause).
// Needs a run with QualityRunOptions::recordMisses.
#include "calib/eval/QualityRun.h"

#include <optional>
#include <string>
#include <vector>

namespace omnitune {

// A markdown table of the missed frames of `variants`, in matrix order; `cause`, when set,
// keeps only the misses of that cause.
std::string missListMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants,
                             std::optional<MissCause> cause = std::nullopt);

// Writes each missed ball's crop, enlarged `scale` times with the ball's true circle (green), the
// candidate at the ball (red, when there was one) and the detection elsewhere (blue, when it lies
// in the crop), to `folder` (created when missing) as "<variant>_<cell>_f<frame>_<cause>.png".
// Returns an error naming the file that failed, or nothing.
std::optional<std::string> writeMissCrops(const QualityRun& run, const std::vector<std::size_t>& variants,
                                          const std::string& folder, std::optional<MissCause> cause = std::nullopt,
                                          int scale = 8);

// The cause named `name` (missCauseName's text, or with '-' for spaces: "non-green",
// "no-candidate"), or nothing.
std::optional<MissCause> missCauseNamed(const std::string& name);

}  // namespace omnitune
