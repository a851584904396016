#pragma once
// A possible ball: a Hough maximum (specific path) or circle (OpenCV path) with the three
// validation scores of thesis section 4.4 / Table 4.1 (plus our run-on score) and the test
// that rejected it.
#include <string_view>

namespace omnitune {

// BlobSeed: a compact non-green blob of ball size (hough.blob_seeds), not a Hough maximum.
enum class CandidateSource { SpecificHough, OpenCvHough, BlobSeed };

std::string_view candidateSourceName(CandidateSource s);

// Whether a second look moved the candidate from where its search put it, and how: to the
// centroid of what is not carpet around a prefilter refusal (validation.recentre_refused), or to
// the centre of the circle fitted to a circularity refusal's border (validation.refit_recentre).
enum class CandidateMove : unsigned char { None, ToColourCentroid, ToCircleFit };

enum class RejectReason {
    None,             // accepted
    OutsideArea,      // centre not on a processed pixel, or the circle reaches the rim (validation.refuse_at_rim)
    RadiusTooLarge,   // OpenCV circle larger than the expected radius at its distance (or, with
                      // opencv_hough.min_radius_ratio, far smaller)
    TooSmall,         // expected radius below validation.min_radius_px: too far to judge the shape
    NonGreen,         // too much green in the ball square
    NonBlack,         // too much black in the ball square (a robot)
    Circularity,      // too few edges at the expected radius
    RunsOn,           // the centre's colour runs on beyond the circle on too many rays: a line corner or end
    LineJunction,     // field lines leave it like spokes, or it is mostly line with one arm (validation.line_arms)
    LineBlob,         // no line arm, but mostly line colour inside (validation.line_blob_armless_min_pct)
    NotChosen,        // valid, but another valid candidate scored higher
};

std::string_view rejectReasonName(RejectReason r);

struct ValidationScores {
    double nonGreenPct = 0.0;    // % of processed pixels in the ball square that are not green
    double nonBlackPct = 0.0;    // % that are not black
    double circularityPct = 0.0; // % of rays that meet an edge at the expected radius +- tolerance
    double borderSpreadPx = 0.0; // std of the radius at which those rays met the edge
    double runOnPct = 0.0;       // % of the judged rays along which the centre's colour class runs
                                 // on beyond the circle (validation.max_run_on_pct)
    // validation.circle_fit: the circle fitted to the border points (0 when none was fitted);
    // centre relative to the candidate, px.
    double fitRadiusPx = 0.0;
    double fitDx = 0.0;
    double fitDy = 0.0;
    // validation.fit_visible_border: the largest gap, along the usable rays, between the fitted
    // and the expected circle's border, px (-1 when no circle was fitted).
    double fitBorderGapPx = -1.0;
    double hintPct = 0.0;        // % of processed square pixels of validation.ball_hint_class
    // Which scores were measured. A pipeline that does not explain its rejections
    // (Pipeline::setExplainRejections) leaves a candidate the area already refused unscored, and
    // one that failed a colour test without its shape: their zeros mean "not measured".
    bool squareMeasured = false;  // nonGreenPct, nonBlackPct, hintPct
    bool shapeMeasured = false;   // circularity, border, run-on and fit scores
};

struct BallCandidate {
    CandidateSource source = CandidateSource::SpecificHough;
    int area = -1;            // radial area index (0-based), -1 when not area-based
    int x = 0;                // centre, px
    int y = 0;
    double distancePx = 0.0;  // to the robot centre
    double radiusPx = 0.0;    // expected radius (specific) or the circle's radius (OpenCV)
    double expectedRadiusPx = 0.0;
    double accumulator = 0.0; // 3x3 Hough sum (specific; scaled up when edge pixels were
                              // subsampled) or 0 (OpenCV gives no votes)
    double score = 0.0;       // 0..1, all validation tests in one number (CandidateScore.h);
                              // the valid candidate with the highest is chosen
    ValidationScores scores;
    RejectReason rejected = RejectReason::None;
    CandidateMove move = CandidateMove::None;
    int searchX = 0;  // with a move: where the search put the centre, px
    int searchY = 0;
};

}  // namespace omnitune
