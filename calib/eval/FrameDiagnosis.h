#pragma once
// Why a ball frame was missed and what a false positive hit, from one pipeline result and the
// frame's truth (issue 9: measure the causes before attacking them). Pure: the quality run
// counts these per cell (calib/eval/QualityRun.h) and the report tabulates them.
#include "calib/session/TruthCsv.h"
#include "core/Config.h"
#include "core/PipelineResult.h"

#include <array>
#include <string_view>

namespace omnitune {

// Why a visible ball was not found within the evaluation's max error. The candidate "at the
// ball" is one whose centre lies inside the true silhouette (truth radius, at least 2 px); of
// several, the one that got farthest through validation speaks for the frame.
enum class MissCause {
    NoCandidate,   // no candidate at the ball: the searches never proposed it
    TooSmall,      // at the ball, but its expected radius is below validation.min_radius_px
    OutOfRange,    // outside the processed area, or an OpenCV circle of the wrong radius
    NonGreen,      // failed the non-green test (too much carpet in its square)
    NonBlack,      // failed the non-black test (too dark)
    Circularity,   // too few rays found its border
    CircleOff,     // enough border, but the fitted circle's radius or centre is off the model
    RunsOn,        // its colour runs on beyond the circle (line corner test)
    LostToOther,   // valid, but another candidate (elsewhere) was chosen
    PositionOff,   // chosen, but its position in metres is off by more than the max error
};
constexpr std::size_t kMissCauseCount = 10;
std::string_view missCauseName(MissCause cause);

// Where a wrong detection sits: at the mirror rim (its circle reaches the outer radius), beside
// the mask (rods, the body's painted edge: a masked pixel within its circle), at the robot body
// (its circle reaches the inner radius) or in the open field.
enum class FalsePositivePlace { Rim, Mask, Body, Field };
constexpr std::size_t kFalsePositivePlaceCount = 4;
std::string_view falsePositivePlaceName(FalsePositivePlace place);

// A false positive: which search proposed it and where it sits. Index: source x place.
struct FalsePositiveKind {
    CandidateSource source = CandidateSource::SpecificHough;
    FalsePositivePlace place = FalsePositivePlace::Field;
};
constexpr std::size_t kCandidateSourceCount = 3;
constexpr std::size_t kFalsePositiveKindCount = kCandidateSourceCount * kFalsePositivePlaceCount;
std::size_t falsePositiveKindIndex(FalsePositiveKind kind);
FalsePositiveKind falsePositiveKindAt(std::size_t index);

// The cause of a miss: `result` did not find the ball of `truth` (visible) within the max error.
// `radiusOff` is set when the candidate at the ball expected a radius farther from the true one
// than the circle fit allows (validation.fit_max_radius_error*): the radius model is off there.
// `atBall` is set to that candidate (candidateAtBall), nullptr when there was none.
MissCause diagnoseMiss(const PipelineResult& result, const TruthRow& truth, const ValidationOptions& validation,
                       bool* radiusOff = nullptr, const BallCandidate** atBall = nullptr);
// The candidate at the ball that got farthest through validation, or nullptr (the miss's witness).
const BallCandidate* candidateAtBall(const PipelineResult& result, const TruthRow& truth,
                                     const ValidationOptions& validation);

// What the detection of `result` (a false positive) hit. `config` is the one the frame ran with.
FalsePositiveKind diagnoseFalsePositive(const PipelineResult& result, const Config& config);

}  // namespace omnitune
