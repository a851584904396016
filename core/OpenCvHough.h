#pragma once
// Thesis section 4.2: circles from cv::HoughCircles (HOUGH_GRADIENT) on the binary image, a
// circle larger than the ball would be at its distance rejected.
//
// Where we differ: the thesis validates only the strongest circle, which on a real field is
// nearly always an artefact at the largest radius (rim speckle, clutter beyond the carpet) and
// is rejected as too large. We walk the circles strongest first and validate up to maxCircles
// whose radius fits the ball's at their distance (the others are reported as rejected, without
// using up the count); maxCircles 1, skipImplausible false and minRadiusRatio 0 give the
// thesis' rule.
#include "core/BallCandidate.h"
#include "core/MaskFill.h"
#include "core/OpenCvRadiusBands.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

class Geometry;
class BallModel;

struct OpenCvHoughOptions {
    // Inverse accumulator resolution (2: half width and height), 1..4. 1 with acc_threshold 10
    // finds more balls with OpenCV alone on the optics tours (41 % instead of 36 %) but fewer
    // with combined (46.5 % instead of 47.1 %, 3 false positives in 1280 frames instead of 1).
    double dp = 2.0;
    double minDist = 12.0;      // px between two circle centres; smaller: neighbours duplicate, larger: balls missed
    double cannyHigh = 180.0;   // HoughCircles' internal Canny high threshold (low is half of it)
    // Accumulator votes a centre needs; lower: more (false) circles. At 20, balls under ~8 px
    // radius are mostly missed on the binary image (measured on drawn balls, 70..230 px out).
    double accThreshold = 12.0;
    int minRadius = 3;          // px
    int maxRadius = 25;         // px
    // A circle is rejected when radius > expected * maxRadiusRatio. The thesis rejects any circle
    // above the expected radius (1.0); HoughCircles' radius of a true ball reaches 1.23x the
    // expected one (99th percentile on drawn balls, dp 2), hence the slack.
    double maxRadiusRatio = 1.25;
    // A circle is rejected when radius < expected * minRadiusRatio (thesis: 0, no lower bound):
    // a speck or a line's rounded end; a true ball's HoughCircles radius is rarely below 0.7x.
    double minRadiusRatio = 0.5;
    // Circles validated per frame, strongest first (thesis: 1).
    int maxCircles = 8;
    // Circles whose radius does not fit (or outside the processed area) do not use up
    // maxCircles (thesis: false, its one circle is the strongest of any radius).
    bool skipImplausible = true;
    // Moves each plausible circle's centre to the centroid of the non-green pixels within its
    // expected radius + 1 px (three sub-pixel steps): HoughCircles' centre is often 2-3 px off
    // a small ball, enough to fail circularity (thesis: false, the circle as found).
    bool refineCentre = true;
    // Combined algorithm: OpenCV's valid circles join the specific candidates in the ranking
    // (true), or OpenCV runs only when the specific search found nothing valid (thesis 4.3).
    bool joinRanking = false;
    // Combined algorithm: the OpenCV search is skipped on a frame whose processed ring holds more
    // edge pixels than this (the specific search's count; 0: never skipped). HoughCircles' time
    // grows with the edges (dim speckle, sensor noise), and on such frames its circles are the
    // speckle's, so the skip bounds the worst frame's time (issue 9 section 6). Measured (optics
    // matrix, 446 ball frames; docs/performance.md): no cap 210 balls / 9 false-positive frames,
    // 2000: 207 / 8, and the combined pipeline's CPU time on the bench's hard frames 1.51 -> 1.10x
    // cv::HoughCircles (specific alone 1.00). The OpenCV algorithm alone always runs it.
    // With the per-ring search (below), 2000 -> 4000 finds combined 283 -> 291 balls (false-
    // positive frames 8 -> 8 of 512; 3000: 286; 5000: 291), but on the bench's hard frames
    // (idle machine) combined's p99 goes from 9.1 to 15.0 ms (3000: 10.6), past issue 9's 10 ms:
    // 2000 keeps the bound. A cap per ring would buy the balls without the time.
    int maxEdgePixels = 2000;
    // Per-ring search (core/OpenCvRadiusBands): the processed area is cut into distance rings in
    // which the expected radius varies by at most this ratio, and cv::HoughCircles runs in each
    // with the ring's radius range (x min/max_radius_ratio). 0: one search over
    // minRadius..maxRadius (thesis). Optics matrix, 2 frames/cell: OpenCV 33.0 -> 42.2 % with
    // 5 -> 4 false-positive frames (span 1.25 then). Since (4 frames/cell, seeds 1-4, 2026-12-04)
    // 1.5 finds more than 1.25: OpenCV 1745 -> 1770 of 3558 balls (false-positive frames 4 -> 5
    // of 3840), combined 2543 -> 2545 (18 -> 17), specific the same, and cv::HoughCircles reads
    // ~40 % fewer pixels (5 rings instead of 9 on the 480x480 spherical mirror). Fewer on the
    // gate's smaller matrix (OpenCV 224 -> 222 of 444, combined the same) and on the bench's 84
    // hard frames (OpenCV alone 46.4 -> 40.5 %). 1.6: 1774 but 8 false-positive frames; 1.75: 1740.
    double bandRadiusSpan = 1.5;
    // Per ring: votes a centre needs per px of the ring's smallest expected circumference (never
    // below bandAccThreshold; 0: accThreshold everywhere: at span 1.5, 0.5 found 29.1 % of the
    // balls against 36.8 % with 0), min_dist as a multiple of that radius, and the plausible circles
    // validated (instead of maxCircles: a frame validates at most rings x bandCircles).
    double bandVotesPerPx = 0.0;
    double bandMinDistRatio = 1.0;
    int bandCircles = 2;
    // Per ring, instead of dp and accThreshold: the image's own accumulator resolution and 8
    // votes. Optics matrix, 2 frames/cell: 42.2 -> 45.3 % of the balls, false-positive frames
    // 4 -> 2 of 512 (on the distractor-free cells: dp 2 with 8 or 6 votes found no more than
    // with 12; dp 1 with 6 or 5 votes 3-4 fewer balls and more false positives).
    double bandDp = 1.0;
    double bandAccThreshold = 8.0;
    // HoughCircles' input has its masked ring pixels within this many px of a non-green pixel
    // made non-green (core/MaskFill.h), so a ball behind a support rod is one disc again; 0: the
    // binary image as it is, masked pixels green (thesis). Optics matrix, 2 frames per cell:
    // OpenCV 42.8 -> 45.3 % of the balls (seed 2: 44.6 -> 45.9 %), its false-positive frames
    // 3 -> 2 (1 -> 1), combined 305 -> 307 balls (297 -> 297); 3 px: 44.1 %, 6 px: 44.6 %
    // (a wider fill grows a ball beside a rod along it). Only the OpenCV search sees it: the
    // specific search votes for masked centres instead (hough.masked_centres).
    int maskFillPx = 4;
    // A circle centred on a masked ring pixel (a ball behind a rod) is validated on its visible
    // part, as hough.masked_centres does for the specific search; off: refused as outside the
    // processed area (thesis).
    bool maskedCentres = true;
    // On the binary input, HoughCircles' Canny drops the rings around one-pixel specks (its high
    // threshold raised to just below a straight border's gradient: core/SpeckFreeEdges.h), as
    // edges.drop_specks does for the specific search; off: canny_high as set (thesis).
    bool dropSpecks = true;
};

class OpenCvHough {
public:
    // Appends up to maxCircles candidates of plausible radius (per ring: bandCircles), and up to
    // maxCircles implausible ones before them marked RadiusTooLarge (too large or too small) or
    // OutsideArea.
    void process(const cv::Mat& binary, const OpenCvHoughOptions& options, const Geometry& geometry,
                 const BallModel& ball, std::vector<BallCandidate>& candidates);

private:
    struct Pass {  // one cv::HoughCircles run's circles, appended
        cv::Point offset;                           // of its image part
        double minDistancePx = 0, maxDistancePx = 0;  // centres kept; max 0: all
        int maxCounted = 0;
    };
    void appendCircles(const cv::Mat& binary, const OpenCvHoughOptions& options, const Geometry& geometry,
                      const BallModel& ball, const Pass& pass, std::vector<BallCandidate>& candidates);

    // A ring's input: the binary image with everything farther than its largest circle from the
    // ring made green, so a noisy frame's far edges cost no radius estimation there (the border
    // this paints is out of every ring centre's reach). `outside` is kept while the ring stays.
    struct RingImage {
        OpenCvRadiusBand band;
        double centreX = 0, centreY = 0;
        cv::Mat outside;  // 255 out of the ring's reach, ROI-sized
        cv::Mat input;
    };
    const cv::Mat& ringInput(const cv::Mat& binary, const Geometry& geometry, std::size_t i);

    MaskFill maskFill_;
    std::vector<cv::Vec3f> circles_;
    std::vector<OpenCvRadiusBand> bands_;
    std::vector<RingImage> rings_;
};

}  // namespace omnitune
