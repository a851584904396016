#pragma once
// A far ball at the carpet's edge (issue 9): beyond the carpet the mirror shows the hall's floor
// out to its rim, and the ball's outer half lies over it. The binary image has no border there
// (ball and floor are both not green), so the circularity's rays outwards found none and the ball
// failed as not round. Such a ray is judged by colour instead: the floor's colour is read just
// beyond the search band, and the ball's border is where the pixels stop differing from it.
#include <opencv2/core.hpp>

#include <array>
#include <cstdint>

namespace omnitune {

// What the hall ray needs to know of a pixel.
class HallPixels {
public:
    virtual ~HallPixels() = default;
    // Inside the image and processed.
    virtual bool known(cv::Point p) const = 0;
    // Carpet: a known pixel of the carpet's own green.
    virtual bool carpet(cv::Point p) const = 0;
    // Beyond the mirror's rim (not merely masked: a rod or our body is no hall floor).
    virtual bool pastRim(cv::Point p) const = 0;
    virtual std::array<std::uint8_t, 3> bgr(cv::Point p) const = 0;
};

// One ray from a candidate's centre: along the unit direction (ca, sa), its border search band
// ends at rMaxPx.
struct HallRaySpan {
    cv::Point2d centre;
    double ca = 1.0;
    double sa = 0.0;
    double rMaxPx = 0.0;
};

struct HallRay {
    bool overFloor = false;  // the ray runs out over the hall floor: judge it by colour
    bool border = false;     // overFloor: the ball's colour ends between rMinPx and rMaxPx
    double borderPx = 0.0;   // border: its distance from the centre
};

// Whether the ray runs out over the hall floor: from the band's end on, it reaches the mirror's
// rim within reachPx and meets no carpet (two carpet pixels in a row; a speck of noise does not
// count) nor a masked pixel first. If so, its border is half a step past the outermost sample up
// to rMaxPx whose colour differs from the floor's (the mean of the pixels 1-3 px past the band)
// by at least minStep (the B, G, R absolute differences added), when that lies between rMinPx
// and rMaxPx. A ray whose colour ends before rMinPx, runs on to rMaxPx, or never differs, has none.
HallRay hallRay(const HallRaySpan& span, double rMinPx, double reachPx, double minStep, const HallPixels& pixels);

}  // namespace omnitune
