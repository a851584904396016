#pragma once
// The specific circular Hough transform of thesis section 4.1: each edge pixel votes for the
// centres of the balls it could belong to, knowing the ball radius at each distance from the
// robot; maxima of the 3x3 sum give ball candidates, one absolute maximum or one per radial
// area (Fig. 4.10, 4.11).
//
// Where we differ from the thesis' text: by default an edge pixel votes on the curve of
// centres c with |c - e| = r(|c|), the radius expected at the *centre's* distance, not on the
// circle of the radius at the edge pixel's own distance. The literal rule shifts every maximum
// outwards (the near side's edges see a bigger radius, the far side's a smaller one): 3 px at
// 80 px from the centre with the default model. `radiusAtCentre = false` restores it.
#include "core/BallCandidate.h"
#include "core/BlobSeeds.h"
#include "core/CandidatePrefilter.h"
#include "core/Geometry.h"

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace omnitune {

class BallModel;

struct SpecificHoughOptions {
    double nearRobotRadius = 70.0;  // px; votes for centres closer than this count nearRobotWeight
    int nearRobotWeight = 2;        // votes per vote near the robot (a ball there is half hidden)
    bool multipleMaxima = true;     // one maximum per radial area (true) or one absolute (false)
    // Upper bounds of the radial areas, px, increasing. Area i spans (bound[i-1], bound[i]].
    std::vector<double> areaBounds = {70, 105, 140, 170, 205, 240};
    int minAccumulator = 1;         // a maximum whose 3x3 sum is below this is no candidate
    bool radiusAtCentre = true;     // vote with the radius at the centre's distance (see above)
    // Local maxima kept per radial area, strongest first (thesis: 1). A kept maximum suppresses
    // weaker ones closer than suppressionRadii expected radii, in its own and other areas.
    int maximaPerArea = 3;
    double suppressionRadii = 1.0;
    // Candidates per frame at most (maxima and seeds): the areas' strongest first, then their
    // second ones, and so on, so each area keeps its best. Bounds the validation time.
    int maxCandidates = 16;
    // Edge pixels that vote per frame at most; beyond it an even, deterministic subsample votes
    // (0: no cap). A clean frame has 1-3 thousand; noise and dim speckle reach tens of thousands.
    int maxEdgePixels = 6000;
    // Seeds from connected non-green blobs whose area matches the ball's at their distance.
    bool blobSeeds = true;
    // Centres may lie on masked pixels inside the ring (a ball behind a support rod): edge pixels
    // vote for them too, and their maxima become candidates, validated on the visible part
    // (masked pixels are unknown there). Off (the thesis): only processed non-green centres.
    bool maskedCentres = true;
    // Choose among valid candidates by the combined score (CandidateScore.h); false: the
    // thesis' best circularity, then most votes.
    bool rankByScore = true;
    // Maxima that validation would refuse on their square's colour or at the rim take no
    // candidate slot (CandidatePrefilter.h): the fraction of validation.min_non_green_pct the
    // class-based non-green share must reach (0: off), and whether the rim test applies.
    double prefilterNonGreen = 0.85;
    bool prefilterRim = true;
    // With prefilterRim and validation.rim_test, a maximum whose circle reaches the rim must pass
    // validation's rim judgement too (its width, inward side and colour): rim clutter otherwise
    // holds the far ring's slots that a far ball's weaker maximum needs.
    bool prefilterRimTest = true;
    double prefilterNonBlack = 1.0;  // fraction of validation.min_non_black_pct (0: off)
    int prefilterChecks = 48;  // maxima tested per area at most (bounds the prefilter's time)
    // Blob seeds are flooded with the black classes counted as background (a ball beside a
    // robot is then a blob of its own); needs the classes image.
    bool seedsWithoutBlack = false;  // off: +1 ball at 2 frames per cell, -3 at 1 (rods cells +3)
    // A seed's box may be as long as the squashed ball's tangential axis (BlobSeeds::find).
    bool seedsSquashed = true;
};

// What one process() call did with the edge pixels.
struct HoughStats {
    int edgePixels = 0;   // edge pixels in the processed ring
    int votingPixels = 0; // of them, how many voted (fewer when maxEdgePixels was exceeded)
    int localMaxima = 0;  // local maxima of the sums considered
    int blobSeeds = 0;    // candidates added from blobs
    int prefiltered = 0;  // maxima and seeds the prefilter refused
    // Of them, the strongest few (up to maxima_per_area per area, and the seeds) are listed
    // after the candidates, rejected with the prefilter's reason and not validated: the table
    // and the miss diagnosis still see what was at the ball.
    int prefilterListed = 0;
    // Only with setListEveryRefusal: the refusals past that cap, listed after those (the miss
    // diagnosis then tells a refused ball from one no search found).
    int prefilterUnlisted = 0;
    // Set by the pipeline after validation (validation.recentre_refused): refusals moved to the
    // centroid of what is not carpet and validated again, and how many of them passed (those
    // are validated candidates now, and no longer counted in prefilterListed).
    int recentreTried = 0;
    int recentred = 0;
};

class SpecificHough {
public:
    SpecificHough() = default;
    // Precomputes the circle offsets per radius, the vote weight image and the area index of
    // every pixel. `options` must have passed checkConfig() (the one place user values are checked).
    // `prefilter` (candidatePrefilterFor) keeps maxima validation would refuse out of the slots.
    SpecificHough(const SpecificHoughOptions& options, const Geometry& geometry, const BallModel& ball,
                  const CandidatePrefilter& prefilter = {});

    // `edges`: CV_8UC1 edge image; `binary`: CV_8UC1, 0 = non-green (where a centre may lie).
    // Fills the vote accumulator, its 3x3 sums and appends the candidates (no allocation once
    // `candidates` has capacity).
    // `classes` (CV_8UC1 class ids, optional) lets the prefilter's non-black test run; `colour`
    // (the frame's, optional) lets it judge black against the carpet around, as validation does.
    void process(const cv::Mat& edges, const cv::Mat& binary, std::vector<BallCandidate>& candidates,
                 const cv::Mat& classes = cv::Mat(), const FrameColour* colour = nullptr);

    const HoughStats& stats() const { return stats_; }

    // Whether every prefilter refusal is listed, not only the strongest few (the evaluation's
    // miss diagnosis; the robot needs only the search). The extra ones come last. Off by default.
    void setListEveryRefusal(bool on) { listEveryRefusal_ = on; }

    // CV_16UC1 votes and CV_32SC1 3x3 sums of the last process() call.
    const cv::Mat& accumulator() const { return accumulator_; }
    const cv::Mat& sums() const { return sums_; }
    int areaCount() const { return int(options_.areaBounds.size()); }

private:
    // Radial area (index into areaBounds) of a centre `distance` px from the robot; beyond the
    // last bound (a larger mirror than the areas cover) it is the last area.
    int areaOf(double distance) const;

    // A vote position relative to an edge pixel: `along` the ray from the robot centre through
    // the pixel and `across` it, px.
    struct LocusPoint { float along; float across; };

    // A local maximum of the sums.
    struct Peak { std::int32_t sum; int x; int y; int rank; };

    void vote(const cv::Mat& edges, const cv::Mat& binary);
    void sum3x3();
    // Fills best_ with at most `cap` kept maxima, in the order they become candidates.
    void findMaxima(const cv::Mat& binary, int cap);
    // Whether a maximum or seed at (x, y) passes the prefilter (counted in stats_ when not);
    // when not and `list`, it joins dropped_ (while there is room) as `source`; otherwise, with
    // listEveryRefusal_, unlisted_.
    bool passesPrefilter(const cv::Mat& binary, int x, int y, std::int32_t sum, CandidateSource source, bool list);
    BallCandidate candidateAt(int x, int y, std::int32_t sum, CandidateSource source) const;

    SpecificHoughOptions options_;
    const Geometry* geometry_ = nullptr;
    const BallModel* ball_ = nullptr;
    // By direction sector, then the edge pixel's rounded distance: one sector without the ball
    // model's per-direction term, kDirectionSectors with it (the ball's size changes round the mirror).
    std::vector<std::vector<LocusPoint>> loci_;
    std::size_t sectors_ = 1;
    std::size_t lociPerSector_ = 0;
    cv::Mat weight_;    // CV_8UC1 votes a processed non-green centre gets: 0 outside the processed ring
    cv::Mat maskedWeight_;  // CV_8UC1 votes a masked centre inside the ring gets (maskedCentres), else 0
    cv::Mat centreVote_;  // CV_8UC1 this frame's vote at each centre: (weight_ & ~binary) | maskedWeight_
    std::vector<RowSpan> centreSpans_;  // where a centre may lie: processed, or masked in the ring
    cv::Mat areaIndex_; // CV_8UC1 radial area of each pixel, 255 = none
    cv::Mat accumulator_;
    cv::Mat sums_;
    std::vector<std::int32_t> rowSums_;
    std::vector<std::vector<Peak>> peaks_;  // by area
    std::vector<Peak> ranked_;
    std::vector<Peak> kept_;
    std::vector<BallCandidate> best_;
    std::vector<BallCandidate> dropped_;  // listed prefilter refusals (capacity fixed at construction)
    std::vector<BallCandidate> unlisted_;  // the other refusals, with listEveryRefusal_
    bool listEveryRefusal_ = false;
    HoughStats stats_;
    CandidatePrefilter prefilter_;
    cv::Mat seedBinary_;  // binary without the black classes, for the seeds
    cv::Mat classes_;  // header of process()'s classes (no copy), for the prefilter
    const FrameColour* colour_ = nullptr;  // process()'s colours, for the prefilter
    double voteScale_ = 1.0;  // edge pixels / voting pixels
    BlobSeeds blobs_;
};

}  // namespace omnitune
