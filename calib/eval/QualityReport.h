#pragma once
// Markdown tables of a quality run (docs/evaluation.md, omnitune-eval --quality-matrix).
#include "calib/eval/QualityRun.h"

#include <string>
#include <vector>

namespace omnitune {

// One row per variant in `variants` (indexes into run.variants): balls found, the worst cell,
// false-positive frames, range bias / std within 4 m, p50 / p99 time per frame.
std::string qualitySummaryMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants);

// Balls found per ball kind, light, distractors and frame size (rows), then per place of the ball
// in its frame (calib/eval/BallPlace.h: range band, out of play), one column per variant.
std::string qualityBreakdownMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants);

// Why the variant missed the balls it missed (calib/eval/FrameDiagnosis.h): one row for all ball
// cells, then one per condition and place as in qualityBreakdownMarkdown; a column per cause, how
// many of the misses had a candidate at the ball whose expected radius was off the true one, and
// how many had one the search's prefilter refused (counted under the test it is named after).
std::string qualityMissesMarkdown(const QualityRun& run, std::size_t variant);

// What the false positives hit (which search proposed them, where they sit), one column per
// variant, with how many came from ball-free frames.
std::string qualityFalsePositivesMarkdown(const QualityRun& run, const std::vector<std::size_t>& variants);

// Each deviation switched to the thesis' value: balls found and false-positive frames beside
// the same algorithm as shipped (the variant without overrides), and the difference.
std::string qualityDeviationsMarkdown(const QualityRun& run);

// The `count` ball cells where the variant found the fewest balls.
std::string qualityWorstCellsMarkdown(const QualityRun& run, std::size_t variant, int count);

// Indexes of the variants without overrides (the algorithms as shipped).
std::vector<std::size_t> shippedVariants(const QualityRun& run);

}  // namespace omnitune
