#pragma once
// What a Hough maximum must show before it takes one of the frame's candidate slots: the two
// validation tests that cost nothing to ask early, so that a ball's weaker maximum is not
// crowded out by line crossings and rim clutter that validation would refuse anyway (issue 9:
// 321 of the 400 maxima beside missed rods-cell balls failed the non-green test).
//
// - Non-green: the share of the ball square's processed pixels that are not field green,
//   by colour class. Validation's own share is never smaller (carpet_by_colour only counts
//   fewer pixels as carpet), so a prefilter threshold at or below validation's refuses only
//   maxima validation would refuse. hough.prefilter_non_green sets it as a fraction of
//   validation.min_non_green_pct (0: off); a known-colour hint skips the test in validation,
//   so it is off then.
// - Rim: with validation.refuse_at_rim, a circle reaching past outer_radius - rim_margin_px is
//   refused (hough.prefilter_rim).
// - Rim test: with hough.prefilter_rim_test (and validation.rim_test), a circle reaching the rim
//   within that margin must also pass validation's rim judgement (core/Validation.h:
//   rimCutBallPasses), which it would otherwise fail only after taking a slot.
// - Non-black: the share of those pixels not of a black class. Validation's is never smaller
//   (validation.black_by_local_carpet counts fewer pixels as black), so a maximum below
//   hough.prefilter_non_black x validation.min_non_black_pct (a robot the ball is behind) is one
//   validation refuses too, at a fraction up to 1. That holds for the class share only; with
//   black_by_local_carpet a maximum the class share refuses is asked again as validation
//   judges black (against the carpet around it), so a ball in a vignetted corner keeps its slot.
#include "core/ColourClasses.h"
#include "core/Validation.h"

#include <opencv2/core.hpp>

#include <limits>

namespace omnitune {

struct Config;

struct CandidatePrefilter {
    double minNonGreenPct = 0.0;  // %; 0: no test
    double minNonBlackPct = 0.0;  // %; 0: no test (needs the classes image)
    ColourRoles roles;            // which class ids are black
    // With validation.black_by_local_carpet a class-share non-black refusal is asked again with
    // nonBlackPctAt (needs the frame's colours), under these options' carpet ring and ratio.
    ValidationOptions validation;
    double maxReachPx = std::numeric_limits<double>::infinity();  // distance + expected radius, px
    // A maximum whose circle reaches the rim must pass validation's rim judgement
    // (rimCutBallPasses, under `validation`): hough.prefilter_rim_test. Needs the classes image.
    bool rimTest = false;
    // A listed colour refusal whose expected radius is below this (validation.min_radius_px) is
    // named "too small", validation's first test, so the table gives the reason validation would;
    // a rim refusal keeps "outside area", which validation checks before size.
    double tooSmallBelowPx = 0.0;

    bool active() const
    {
        return minNonGreenPct > 0.0 || minNonBlackPct > 0.0 || maxReachPx < std::numeric_limits<double>::infinity();
    }
};

// The prefilter `config`'s validation implies (hough.prefilter_non_green, hough.prefilter_rim).
CandidatePrefilter candidatePrefilterFor(const Config& config);

// % of the processed pixels (`used` non-zero) of the square of odd side `side` centred at (x, y)
// that `binary` (CV_8UC1, 255 = green or unprocessed) marks non-green, and that `classes`
// (CV_8UC1 class ids; may be empty, then nonBlack is 100) has in no black class; 0 when none is
// processed.
struct SquareShares {
    double nonGreenPct = 0.0;
    double nonBlackPct = 0.0;
};
SquareShares classSquareShares(const cv::Mat& binary, const cv::Mat& classes, const cv::Mat& used,
                               const ColourRoles& roles, int x, int y, int side);

}  // namespace omnitune
