#pragma once
// The carpet's own colour next to a candidate, so that green on the ball (panels of a
// green-and-white ball, its shaded side) is told from the carpet: the colour class says only
// "green", this says "the green of the carpet right here". Measured per candidate from the
// field-class pixels of a ring around it, so that vignetting, uneven light and each venue's
// carpet shade need no calibration.
#include "core/ColourClasses.h"
#include "core/FrameColour.h"

#include <opencv2/core.hpp>

namespace omnitune {

class Geometry;

struct CarpetTolerance {
    double sigmas = 3.0;     // spreads of the ring's own colour a carpet pixel may differ by
    double hue = 8.0;        // hue units (0..179); never tighter than this
    double saturation = 40;  // 0..255; never tighter than this
    // 0..255; brightness is judged too when positive (never tighter than this). Off by default:
    // shadows on the carpet differ from it by brightness alone.
    double value = 0;
};

class CarpetColour {
public:
    CarpetColour() = default;
    // The processed pixels of a field class between `inner` and `outer` px around (x, y).
    static CarpetColour around(const FrameColour& frame, const cv::Mat& classes, const Geometry& geometry,
                               const ColourRoles& roles, int x, int y, double inner, double outer);

    // Enough carpet was seen around the candidate to judge colours by it.
    bool valid() const { return samples_ >= kMinSamples; }
    int samples() const { return samples_; }
    double hue() const { return hue_; }  // circular mean, 0..180 (a red carpet's wraps through 0)
    double saturation() const { return sat_; }
    double value() const { return val_; }  // mean V, 0..255

    // Whether `c` is the carpet's colour (always true when not valid()).
    bool matches(const Hsv& c, const CarpetTolerance& t) const;
    // Whether a pixel of brightness `v` is darker than the carpet by more than `tolerance` (and
    // than `sigmas` of its spread): a ball's shaded side, not the carpet (false when not valid()).
    bool darker(double v, double tolerance, double sigmas) const;

private:
    static constexpr int kMinSamples = 12;
    int samples_ = 0;
    double hue_ = 0;
    double sat_ = 0;
    double val_ = 0;
    double hueSpread_ = 0;
    double satSpread_ = 0;
    double valSpread_ = 0;
};

}  // namespace omnitune
