#pragma once
// Where a ball frame's ball lay, for the quality report's per-frame rows: its true range from the
// robot, in bands (the matrix spreads its frames 0.5-5 m, and the far band holds nearly half
// of the misses), and whether it lay wholly beyond the field's outer lines, out of play. The matrix
// keeps every ball on the carpet (calib/sim/optics/OpticsCell.cpp, keepBallOnCarpet) by sliding a
// ball drawn past it to the carpet's edge, 1 m beyond the lines, where its image lies over the
// hall floor: the rows say how many of the figures are such balls, without leaving them out.
#include "calib/session/TruthCsv.h"

#include <array>
#include <cstddef>

namespace omnitune {

struct FieldDimensions;

enum class BallPlace { Under2m, From2To3m, From3To4m, From4m, OutOfPlay };
constexpr std::size_t kBallPlaceCount = 5;

// "range: under 2 m", ..., "place: beyond the outer lines (out of play)".
const char* ballPlaceName(BallPlace place);

// The places a visible ball belongs to: one range band (from truth xM, yM), and OutOfPlay when
// the truth's robot pose puts the ball, of radius `ballRadiusM`, wholly past an outer line of
// `field` (without a pose: never). Indexed by BallPlace.
std::array<bool, kBallPlaceCount> ballPlacesOf(const TruthRow& truth, const FieldDimensions& field, double ballRadiusM);

}  // namespace omnitune
