#pragma once
// A ball touching a field line. In the colour classes the ball's border against the line is a
// change from the ball's colours to the line class; in the thesis' green / non-green image there
// is no edge there at all (ball and line are both non-green), so a circularity ray that leaves
// the ball into the line finds no border and runs on to the line's far side. Such a ray says
// nothing of the ball's shape, like a ray into a robot or a masked rod: the validation leaves it
// out (validation.line_rays_unknown), and the ball is judged on the rays that open onto carpet.
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

// Follows one ray walking out from a candidate's centre, pixel by pixel, and tells when it
// leaves the candidate's own colours (any class that is neither field nor line) into a line
// that goes on beyond the circle. Only a ray that crossed nothing but the candidate's colours
// from the centre to at least `minEntryPx` counts: a line corner or line end (its centre on the
// line, a few unclassified pixels at its blurred borders) never does; the run-on test judges
// those. A line that ends soon after (a white panel of the ball ending at the ball's border)
// is no line contact either.
class LineContactRay {
public:
    // `x`, `y` the centre, (ca, sa) the ray's unit direction; the line must start at
    // `minEntryPx` or farther and go on to `reachPx` from the centre (masked pixels do not break
    // it, carpet and black do).
    LineContactRay(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y, double ca,
                   double sa, double minEntryPx, double reachPx);

    // The next processed pixel of the ray, `r` px from the centre (in walking order): true when
    // the ray leaves the candidate's colours into such a line here.
    bool entersLine(cv::Point p, double r);

private:
    bool lineGoesOn(double fromR) const;

    const cv::Mat& classes_;
    const Geometry& geometry_;
    const ColourRoles& roles_;
    int x_;
    int y_;
    double ca_;
    double sa_;
    double minEntryPx_;
    double reachPx_;
    bool ownSoFar_ = true;  // every processed pixel so far had one of the candidate's colours
};

}  // namespace omnitune
