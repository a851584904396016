#pragma once
// The mirror rim from one or a few frames: the boundary between the bright mirror image and the
// dark outside (camera housing), found along rays from a first-guess centre and fitted with a
// robust circle. Gives the mirror centre (sub-pixel) and proposes the outer radius of the
// processed ring a margin inside the rim, so the rim's dark edge never reaches Canny.
//
// The rim is found where a ray, walked inwards from the frame border, first turns bright after a
// dark stretch. Rays that reach the border still inside the mirror (a mirror cut by the frame)
// give no point; rays through a dark object touching the rim give a point inside it, which the
// robust fit drops.
#include "calib/fit/CircleFit.h"
#include "calib/fit/FitError.h"
#include "core/Geometry.h"
#include "core/Progress.h"

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace omnitune {

struct RimFitOptions {
    int rays = 360;                  // rays cast from the first-guess centre, evenly over 360 deg
    double darkRunPx = 3.0;          // px of dark the outside must show beyond the rim along a ray
    double brightRunPx = 3.0;        // px of bright the mirror must show inside the rim along a ray
    // px; outer radius proposed this far inside the found rim (its half-level crossing): far
    // enough that the rim's blur gives no edges in the ring, near enough that a ball at the rim
    // keeps its outer border (validation.refuse_at_rim refuses a circle crossing the outer
    // radius). Optics matrix, 2 frames per ball cell (446 ball frames, 512 frames; combined /
    // specific balls found, false-positive frames): 4 px 209 / 204 balls, 9 / 4 FP; 3 px 214 /
    // 208, 13 / 8; 2 px 226 / 222, 12 / 8 (none more at the rim); 1 px 234 / 228, 13 / 9 (rim
    // false positives 1 -> 3). A blurrier real rim may need more: omnitune-calibrate rim --margin.
    double marginPx = 2.0;
    double minContrast = 30.0;       // grey levels between the dark and the bright part of the frames
    double darkShare = 0.25;         // the outside must be as dark as the darkest quarter of the way from the
                                     // frames' 2nd to their 98th grey-level percentile (else the "edge" is a
                                     // line or a shade inside a mirror that fills the frame)
    int minPoints = 24;              // rim points the circle needs
    double minCoverageDeg = 90.0;    // deg of the rim the kept points must span
    std::optional<cv::Point2d> initialCentre;  // first guess; unset: centroid of the bright pixels
    CircleFitOptions circle;
};

struct RimFit {
    cv::Point2d centre;              // mirror centre, px (pixel centres at integers)
    double rimRadius = 0.0;          // px, where the mirror image meets the dark outside
    double outerRadius = 0.0;        // px, proposed geometry.outer_radius: rimRadius - marginPx
    double rmsPx = 0.0;              // geometric residual RMS of the kept rim points
    double coverageDeg = 0.0;        // how much of the rim the kept points span
    double threshold = 0.0;          // grey level that split dark from bright
    int raysCast = 0;
    std::vector<cv::Point2d> points; // rim points found (for an overlay)
    std::vector<bool> inlier;        // per point: kept by the circle fit
    int inliers = 0;
};

struct RimFitResult {
    RimFit fit;                      // meaningful only when ok()
    std::optional<FitError> error;

    bool ok() const { return !error.has_value(); }
};

// `frames`: BGR, grey or UYVY images of one camera; their mean is searched, so a few frames
// average out noise and moving objects at the rim. `progress` may be null.
RimFitResult fitRim(const std::vector<cv::Mat>& frames, const RimFitOptions& options = {},
                    Progress* progress = nullptr);

// Writes the fit into the geometry: centre, outer radius, and the frames' size.
void applyRimFit(const RimFit& fit, cv::Size frameSize, GeometryOptions& geometry);

}  // namespace omnitune
