#pragma once
// A second look at the prefilter's non-green refusals. A green-and-white ball's Hough maximum
// lies on its white half (its green panels make no edge against the carpet), so the square there
// is mostly carpet by class and the prefilter refuses it, and validation would refuse it there
// too. Moved to the centroid of the pixels around it that are not the carpet's own colour (white
// panels and green panels of another shade alike), the square is the ball's: validated there, it
// replaces the refusal when it passes and its green is the ball's (recentre_min_panel_pct).
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

struct RecentreCounts {
    int tried = 0;  // refusals moved and validated again
    int kept = 0;   // of them, how many passed and replaced their refusal
};

// For the candidates [first, end) refused on the non-green test whose nonGreenPct reaches
// options.recentreMinNonGreenPct, up to options.recentreRefused of them (strongest first, as
// listed): three centroid steps, then validation at the new centre. A candidate that passes
// there replaces its refusal and moves to the front of [first, end), so that the refusals stay
// the tail (the window shows the tail's shape as never measured): [first, first + kept) are
// the kept ones. `binary` is the front end's (0 = non-green), for the class share.
RecentreCounts recentreRefusals(std::vector<BallCandidate>& candidates, std::size_t first, std::size_t end,
                                const cv::Mat& binary,
                                const cv::Mat& classes, const cv::Mat& edges, const Geometry& geometry,
                                const BallModel& ball, const ValidationOptions& options, const FrameColour& colour,
                                const ColourRoles& roles);

}  // namespace omnitune
