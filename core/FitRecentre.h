#pragma once
// A second look at candidates refused on their shape whose border fits a circle elsewhere. A
// Hough maximum a few pixels off the ball's centre (a rod or a panel pulls the votes) is refused
// as "circle off model": the circle fitted to its border is the ball's, but its centre lies past
// the allowance from the maximum. Moved to the fitted centre and validated there, it replaces
// the refusal when it passes.
#include "core/BallCandidate.h"
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

#include <cstddef>
#include <vector>

namespace omnitune {

class BallModel;
class FrameColour;
class Geometry;
struct ValidationOptions;

// For the candidates [0, end) refused on circularity with a fitted circle (options.circleFit),
// up to options.refitRecentre of them in list order: a candidate at the fitted centre (on a
// processed pixel), with the expected radius there, validated once. One that passes replaces
// the refusal in place. Returns how many did. `stopAtColour` as validateCandidate's.
int recentreOnFits(std::vector<BallCandidate>& candidates, std::size_t end, const cv::Mat& classes, const cv::Mat& edges,
                   const Geometry& geometry, const BallModel& ball, const ValidationOptions& options,
                   const FrameColour* colour, const ColourRoles& roles, bool stopAtColour);

}  // namespace omnitune
