#pragma once
// A ball touching an object that is neither carpet nor robot black: a person's feet, a robot's
// grey or coloured parts, a second ball. In the thesis' green / non-green image ball and object
// are one non-green blob, so a circularity ray that leaves the ball into the object finds no
// border and counts against a round ball. When the candidate's centre has a ball class (the
// team's ball colour, e.g. orange after Auto colours), the ball's border there is where that
// class ends: a ray that crossed only the ball's class (and its shaded, black side) and then runs
// into such an object, which goes on beyond the circle, says nothing of the ball's shape and is
// left out (validation.foreign_rays_unknown), like a ray into a robot or along a line.
#include "core/ColourClasses.h"

#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

class ForeignContactRay {
public:
    // `ballClass` the candidate's own ball class (Unknown: the centre has none, and no ray is
    // ever a contact). (x, y) the centre, (ca, sa) the unit direction; the object must start at
    // `minEntryPx` or farther and reach `reachPx` from the centre without carpet in between.
    ForeignContactRay(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, ColorClass ballClass,
                      int x, int y, double ca, double sa, double minEntryPx, double reachPx);

    // The next processed pixel of the ray, `r` px from the centre (in walking order): true when
    // the ray leaves the ball's class into such an object here.
    bool entersObject(cv::Point p, double r);

private:
    bool objectGoesOn(double fromR) const;

    const cv::Mat& classes_;
    const Geometry& geometry_;
    const ColourRoles& roles_;
    std::uint8_t ball_;
    int x_;
    int y_;
    double ca_;
    double sa_;
    double minEntryPx_;
    double reachPx_;
    bool ownSoFar_;  // every processed pixel so far had the ball's class (or black: its shade)
};

// The ball class a candidate centred at (x, y) has: the ball-role class of most of the 3 x 3
// pixels around it (Unknown: none holds five of them).
ColorClass ballClassAt(const cv::Mat& classes, const ColourRoles& roles, int x, int y);

}  // namespace omnitune
