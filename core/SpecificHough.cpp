#include "core/SpecificHough.h"

#include "core/BallModel.h"
#include "core/FillBytes.h"
#include "core/Geometry.h"
#include "core/ExpectedRadius.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace omnitune {

namespace {

// Direction sectors of the voting loci when the ball model has a per-direction term: 11.25 deg
// each, so the term's change across a sector stays under ~1 % of the radius (a resolution of
// the table, not a tuning threshold).
constexpr std::size_t kDirectionSectors = 32;

}  // namespace

SpecificHough::SpecificHough(const SpecificHoughOptions& options, const Geometry& geometry, const BallModel& ball,
                             const CandidatePrefilter& prefilter)
    : options_(options), geometry_(&geometry), ball_(&ball), prefilter_(prefilter)
{
    // User values are checked once, by checkConfig(); this guards the area index image (one
    // byte per pixel, 255 = none) against a caller that skipped it.
    const auto& b = options.areaBounds;
    CV_Assert(!b.empty() && b.size() < 255);

    // For each edge distance d, the centres a ball edge there may belong to: in direction phi
    // from the ray, at the radius r solving r = R(d + r cos phi), about one point per pixel of
    // arc. A few fixed-point steps converge: |dR/dd| is far below 1 for any sane ball model.
    // With the per-direction term each sector of directions gets its own loci, evaluated at the
    // sector's middle angle (radiusAt(d, a) is radiusAt(d) without the term).
    const int maxEdgeDistance = int(std::ceil(geometry.options().outerRadius)) + 1;
    const bool directional = ball.options().directionCos != 0.0 || ball.options().directionSin != 0.0;
    sectors_ = directional ? kDirectionSectors : 1;
    lociPerSector_ = std::size_t(maxEdgeDistance) + 1;
    loci_.resize(sectors_ * lociPerSector_);
    for (std::size_t s = 0; s < sectors_; ++s) {
        const double a = -M_PI + 2.0 * M_PI * (double(s) + 0.5) / double(sectors_);
        for (int d = 0; d <= maxEdgeDistance; ++d) {
            const double r0 = ball.radiusAt(d, a);
            const int n = std::max(8, int(std::ceil(2.0 * M_PI * r0)));
            auto& locus = loci_[s * lociPerSector_ + std::size_t(d)];
            for (int k = 0; k < n; ++k) {
                const double phi = 2.0 * M_PI * k / n;
                double r = r0;
                for (int it = 0; it < 6 && options.radiusAtCentre; ++it)
                    r = ball.radiusAt(std::max(0.0, d + r * std::cos(phi)), a);
                locus.push_back({float(r * std::cos(phi)), float(r * std::sin(phi))});
            }
        }
    }

    const cv::Size size = geometry.imageSize();
    weight_.create(size, CV_8UC1);
    maskedWeight_.create(size, CV_8UC1);
    areaIndex_.create(size, CV_8UC1);
    // A centre may lie on a masked pixel of the ring (a ball behind a rod): Geometry says which.
    const cv::Mat& maskedInRing = geometry.maskedInRing();
    for (int y = 0; y < size.height; ++y) {
        int spanStart = -1;
        for (int x = 0; x <= size.width; ++x) {
            bool centre = false;
            if (x < size.width) {
                const double d = geometry.distanceAt(x, y);
                const bool used = geometry.isUsed(x, y);
                const bool masked =
                    options.maskedCentres && !maskedInRing.empty() && maskedInRing.at<std::uint8_t>(y, x) != 0;
                const auto w = std::uint8_t(d < options.nearRobotRadius ? options.nearRobotWeight : 1);
                weight_.at<std::uint8_t>(y, x) = used ? w : 0;
                maskedWeight_.at<std::uint8_t>(y, x) = masked ? w : 0;
                centre = used || masked;
                areaIndex_.at<std::uint8_t>(y, x) = centre ? std::uint8_t(options.multipleMaxima ? areaOf(d) : 0) : 255;
            }
            if (centre && spanStart < 0) spanStart = x;
            if (!centre && spanStart >= 0) {
                centreSpans_.push_back({y, spanStart, x});
                spanStart = -1;
            }
        }
    }
    centreVote_ = cv::Mat::zeros(size, CV_8UC1);
    accumulator_ = cv::Mat::zeros(size, CV_16UC1);
    sums_ = cv::Mat::zeros(size, CV_32SC1);
    rowSums_.assign(std::size_t(size.width) * 3, 0);
    peaks_.resize(options.multipleMaxima ? b.size() : 1);
    best_.reserve(std::size_t(std::max(1, options.maxCandidates)));
    dropped_.reserve(peaks_.size() * std::size_t(std::max(1, options.maximaPerArea)) +
                     std::size_t(std::max(1, options.maxCandidates)));
}

int SpecificHough::areaOf(double distance) const
{
    const auto& b = options_.areaBounds;
    const auto it = std::lower_bound(b.begin(), b.end(), distance);
    return int(std::min<std::size_t>(std::size_t(it - b.begin()), b.size() - 1));
}

BallCandidate SpecificHough::candidateAt(int x, int y, std::int32_t sum, CandidateSource source) const
{
    BallCandidate c;
    c.source = source;
    c.x = x;
    c.y = y;
    c.accumulator = std::round(sum * voteScale_);
    c.distancePx = geometry_->distanceAt(x, y);
    c.area = areaOf(c.distancePx);
    c.expectedRadiusPx = expectedRadiusAt(*geometry_, *ball_, x, y);
    c.radiusPx = c.expectedRadiusPx;
    return c;
}

void SpecificHough::process(const cv::Mat& edges, const cv::Mat& binary, std::vector<BallCandidate>& candidates,
                            const cv::Mat& classes, const FrameColour* colour)
{
    CV_Assert(classes.empty() || (classes.type() == CV_8UC1 && classes.size() == binary.size()));
    classes_ = classes;
    colour_ = colour;
    const cv::Size size = geometry_->imageSize();
    CV_Assert(edges.type() == CV_8UC1 && edges.size() == size);
    CV_Assert(binary.type() == CV_8UC1 && binary.size() == size);
    stats_ = HoughStats{};
    dropped_.clear();
    unlisted_.clear();
    vote(edges, binary);
    sum3x3();
    // Seeds keep up to a quarter of the candidate budget; the maxima get the rest.
    const std::vector<BlobSeed>* seeds = nullptr;
    int reserved = 0;
    if (options_.blobSeeds) {
        // A ball beside a robot is one non-green region with it, too large for a seed; without
        // the black classes the ball's own colours are a region of their own.
        const cv::Mat* seedImage = &binary;
        if (options_.seedsWithoutBlack && !classes.empty()) {
            binary.copyTo(seedBinary_);  // allocates only on the first frame
            for (const RowSpan& s : geometry_->spans()) {
                const std::uint8_t* c = classes.ptr<std::uint8_t>(s.y);
                std::uint8_t* b = seedBinary_.ptr<std::uint8_t>(s.y);
                for (int x = s.x0; x < s.x1; ++x)
                    if (prefilter_.roles.black(c[x])) b[x] = 255;
            }
            seedImage = &seedBinary_;
        }
        seeds = &blobs_.find(*seedImage, *geometry_, *ball_, std::max(1, options_.maxCandidates / 4),
                             options_.seedsSquashed);
        reserved = int(seeds->size());
    }
    findMaxima(binary, std::max(1, options_.maxCandidates - reserved));
    const std::size_t first = candidates.size();
    for (const BallCandidate& b : best_) candidates.push_back(b);
    if (seeds) {
        const std::size_t maxima = candidates.size();
        for (const BlobSeed& seed : *seeds) {
            if (int(candidates.size() - first) >= options_.maxCandidates) break;
            // A maximum on the blob already stands for it.
            const double r = expectedRadiusAt(*geometry_, *ball_, seed.x, seed.y);
            bool covered = false;
            for (std::size_t i = first; i < maxima && !covered; ++i)
                covered = std::hypot(candidates[i].x - seed.x, candidates[i].y - seed.y) < 0.5 * r;
            const std::int32_t sum = sums_.ptr<std::int32_t>(seed.y)[seed.x];
            if (covered || !passesPrefilter(binary, seed.x, seed.y, sum, CandidateSource::BlobSeed, true)) continue;
            candidates.push_back(candidateAt(seed.x, seed.y, sum, CandidateSource::BlobSeed));
            ++stats_.blobSeeds;
        }
    }
    for (const BallCandidate& d : dropped_) candidates.push_back(d);
    for (const BallCandidate& d : unlisted_) candidates.push_back(d);
    stats_.prefilterListed = int(dropped_.size());
    stats_.prefilterUnlisted = int(unlisted_.size());
    classes_ = cv::Mat();  // holds no reference to the caller's image between calls
    colour_ = nullptr;
}

void SpecificHough::vote(const cv::Mat& edges, const cv::Mat& binary)
{
    const int w = edges.cols;
    const int h = edges.rows;
    const auto& spans = geometry_->spans();

    // The cap: count the edge pixels first; beyond the cap, a Bresenham-like stride lets an
    // evenly spread `cap` of them vote (deterministic: same frame, same votes).
    std::int64_t count = 0;
    for (const RowSpan& s : spans) {
        const std::uint8_t* e = edges.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) count += e[x] != 0;
    }
    const std::int64_t cap = options_.maxEdgePixels > 0 ? std::min<std::int64_t>(count, options_.maxEdgePixels) : count;
    std::int64_t phase = 0;
    int voting = 0;

    // Votes: every edge pixel adds its weight on its locus, at centres that are processed and
    // not green (binary 0): weight & ~binary is the weight where binary is 0, else 0; and at
    // masked centres inside the ring (maskedCentres), whose colour is unknown (a masked centre
    // has binary 255 and weight 0; its vote comes from maskedWeight_).
    // One look-up per vote instead of three: this frame's vote at every centre (zero outside
    // centreSpans_ since construction, where both weights are zero).
    for (const RowSpan& s : centreSpans_) {
        const std::uint8_t* used = weight_.ptr<std::uint8_t>(s.y);
        const std::uint8_t* masked = maskedWeight_.ptr<std::uint8_t>(s.y);
        const std::uint8_t* bin = binary.ptr<std::uint8_t>(s.y);
        std::uint8_t* out = centreVote_.ptr<std::uint8_t>(s.y);
        for (int x = s.x0; x < s.x1; ++x) out[x] = std::uint8_t((used[x] & std::uint8_t(~bin[x])) | masked[x]);
    }
    const std::uint8_t* centreVote = centreVote_.data;
    const std::size_t voteStep = centreVote_.step[0];
    auto* accumulator = reinterpret_cast<std::uint16_t*>(accumulator_.data);
    const std::size_t accumulatorStep = accumulator_.step1(0);

    const double cx0 = geometry_->options().centerX;
    const double cy0 = geometry_->options().centerY;
    fillBytes(accumulator_, 0);
    for (const RowSpan& s : spans) {
        const std::uint8_t* e = edges.ptr<std::uint8_t>(s.y);
        const float* dist = geometry_->distance().ptr<float>(s.y);
        for (int x = s.x0; x < s.x1; ++x) {
            if (!e[x]) continue;
            if (cap < count) {
                phase += cap;
                if (phase < count) continue;
                phase -= count;
            }
            ++voting;
            if (dist[x] < 0.5f) continue;
            const float nx = float((x - cx0) / dist[x]);  // unit ray from the robot centre
            const float ny = float((s.y - cy0) / dist[x]);
            std::size_t sector = 0;
            if (sectors_ > 1) {
                const double a = std::atan2(double(ny), double(nx));
                sector = std::min(sectors_ - 1, std::size_t((a + M_PI) / (2.0 * M_PI) * double(sectors_)));
            }
            const auto& locus =
                loci_[sector * lociPerSector_ + std::min(std::size_t(cvRound(dist[x])), lociPerSector_ - 1)];
            int lastDx = INT_MIN;
            int lastDy = INT_MIN;
            for (const LocusPoint& p : locus) {
                const int dx = cvRound(p.along * nx - p.across * ny);
                const int dy = cvRound(p.along * ny + p.across * nx);
                if (dx == lastDx && dy == lastDy) continue;  // neighbouring samples, same pixel
                lastDx = dx;
                lastDy = dy;
                const int cx = x + dx;
                const int cy = s.y + dy;
                if (unsigned(cx) >= unsigned(w) || unsigned(cy) >= unsigned(h)) continue;
                accumulator[std::size_t(cy) * accumulatorStep + std::size_t(cx)] +=
                    centreVote[std::size_t(cy) * voteStep + std::size_t(cx)];
            }
        }
    }
    stats_.edgePixels = int(count);
    stats_.votingPixels = voting;
    voteScale_ = voting > 0 ? double(count) / voting : 1.0;
}

void SpecificHough::sum3x3()
{
    const int w = accumulator_.cols;
    const int h = accumulator_.rows;
    // 3x3 sums: horizontal sums in a 3-row ring, then vertical. Border rows/columns stay 0.
    auto rowSum = [&](int y) -> std::int32_t* {
        std::int32_t* out = rowSums_.data() + std::size_t(y % 3) * std::size_t(w);
        const std::uint16_t* a = accumulator_.ptr<std::uint16_t>(y);
        out[0] = out[w - 1] = 0;
        for (int x = 1; x < w - 1; ++x) out[x] = a[x - 1] + a[x] + a[x + 1];
        return out;
    };
    cv::Mat top = sums_.row(0);
    cv::Mat bottom = sums_.row(h - 1);
    fillBytes(top, 0);
    fillBytes(bottom, 0);
    if (h >= 3) {
        rowSum(0);
        rowSum(1);
        for (int y = 1; y < h - 1; ++y) {
            const std::int32_t* down = rowSum(y + 1);
            const std::int32_t* up = rowSums_.data() + std::size_t((y - 1) % 3) * std::size_t(w);
            const std::int32_t* mid = rowSums_.data() + std::size_t(y % 3) * std::size_t(w);
            std::int32_t* out = sums_.ptr<std::int32_t>(y);
            for (int x = 0; x < w; ++x) out[x] = up[x] + mid[x] + down[x];
        }
    }
}

bool SpecificHough::passesPrefilter(const cv::Mat& binary, int x, int y, std::int32_t sum, CandidateSource source,
                                    bool list)
{
    if (!prefilter_.active()) return true;
    const double d = geometry_->distanceAt(x, y);
    RejectReason why = RejectReason::None;
    SquareShares shares;
    const double radius = expectedRadiusAt(*geometry_, *ball_, x, y);
    if (d + radius > prefilter_.maxReachPx) {
        why = RejectReason::OutsideArea;
    } else if (prefilter_.rimTest && !classes_.empty() &&
               !rimCutBallPasses(classes_, *geometry_, prefilter_.roles, x, y, d, radius, ball_->squashAt(d),
                                 prefilter_.validation, colour_)) {
        why = RejectReason::OutsideArea;
    } else if (prefilter_.minNonGreenPct > 0.0 || prefilter_.minNonBlackPct > 0.0) {
        // The square validation's colour tests read (Validation.cpp: validateCandidate).
        const int side = ball_->squareSizeAt(d, imageAngleAt(*geometry_, x, y));
        shares = classSquareShares(binary, classes_, geometry_->usedMask(), prefilter_.roles, x, y, side);
        if (shares.nonGreenPct < prefilter_.minNonGreenPct)
            why = RejectReason::NonGreen;
        else if (shares.nonBlackPct < prefilter_.minNonBlackPct) {
            // Validation's own share counts black against the carpet around (vignetting).
            if (prefilter_.validation.blackByLocalCarpet && colour_ && !classes_.empty())
                shares.nonBlackPct = nonBlackPctAt(x, y, radius, side, classes_, *geometry_, prefilter_.validation,
                                                   colour_, prefilter_.roles);
            if (shares.nonBlackPct < prefilter_.minNonBlackPct) why = RejectReason::NonBlack;
        }
    }
    if (why == RejectReason::None) return true;
    ++stats_.prefiltered;
    const bool listed = list && dropped_.size() < dropped_.capacity();
    if (listed || listEveryRefusal_) {
        BallCandidate c = candidateAt(x, y, sum, source);
        // A colour refusal is named as validation would name it; a rim refusal stays one, as there.
        c.rejected = why != RejectReason::OutsideArea && c.expectedRadiusPx < prefilter_.tooSmallBelowPx
                         ? RejectReason::TooSmall
                         : why;
        c.scores.nonGreenPct = shares.nonGreenPct;
        c.scores.nonBlackPct = shares.nonBlackPct;
        c.scores.squareMeasured = why != RejectReason::OutsideArea;
        (listed ? dropped_ : unlisted_).push_back(c);
    }
    return false;
}

void SpecificHough::findMaxima(const cv::Mat& binary, int cap)
{
    best_.clear();
    // The scaled sum must reach minAccumulator (and be positive).
    const std::int32_t minRaw =
        std::max<std::int32_t>(1, std::int32_t(std::ceil(options_.minAccumulator / voteScale_ - 1e-9)));
    const int perArea = options_.multipleMaxima ? options_.maximaPerArea : 1;

    if (perArea == 1) {
        // The thesis: the absolute maximum of each radial area (or of the ring).
        std::vector<Peak>& top = kept_;
        top.assign(std::size_t(areaCount()), Peak{0, 0, 0, 0});
        for (const RowSpan& s : centreSpans_) {
            const std::int32_t* sum = sums_.ptr<std::int32_t>(s.y);
            const std::uint8_t* area = areaIndex_.ptr<std::uint8_t>(s.y);
            for (int x = s.x0; x < s.x1; ++x) {
                if (area[x] == 255) continue;
                Peak& b = top[area[x]];
                if (sum[x] > b.sum) b = Peak{sum[x], x, s.y, 0};
            }
        }
        for (const Peak& p : top) {
            if (p.sum < minRaw) continue;
            if (int(best_.size()) >= cap) break;
            best_.push_back(candidateAt(p.x, p.y, p.sum, CandidateSource::SpecificHough));
        }
        stats_.localMaxima = int(best_.size());
        return;
    }

    // Local maxima of the sums (strictly above the neighbours before them in raster order, at
    // least equal to those after: one pixel per plateau), by radial area.
    for (auto& p : peaks_) p.clear();
    const int w = sums_.cols;
    const int h = sums_.rows;
    for (const RowSpan& s : centreSpans_) {
        if (s.y < 1 || s.y >= h - 1) continue;
        const std::int32_t* up = sums_.ptr<std::int32_t>(s.y - 1);
        const std::int32_t* mid = sums_.ptr<std::int32_t>(s.y);
        const std::int32_t* down = sums_.ptr<std::int32_t>(s.y + 1);
        const std::uint8_t* area = areaIndex_.ptr<std::uint8_t>(s.y);
        for (int x = std::max(1, s.x0); x < std::min(w - 1, s.x1); ++x) {
            const std::int32_t v = mid[x];
            if (v < minRaw || area[x] == 255) continue;
            if (v <= up[x - 1] || v <= up[x] || v <= up[x + 1] || v <= mid[x - 1]) continue;
            if (v < mid[x + 1] || v < down[x - 1] || v < down[x] || v < down[x + 1]) continue;
            peaks_[area[x]].push_back(Peak{v, x, s.y, 0});
            ++stats_.localMaxima;
        }
    }

    // Per area, greedy non-maximum suppression from the strongest: a kept maximum suppresses
    // weaker ones within suppressionRadii expected radii. Only the strongest few per area can
    // matter (each kept one suppresses a handful of ridge maxima), so only they are sorted.
    auto stronger = [](const Peak& a, const Peak& b) {
        if (a.sum != b.sum) return a.sum > b.sum;
        return a.y != b.y ? a.y < b.y : a.x < b.x;
    };
    auto suppresses = [&](const Peak& k, const Peak& p) {
        const double r = options_.suppressionRadii * expectedRadiusAt(*geometry_, *ball_, k.x, k.y);
        const double dx = k.x - p.x;
        const double dy = k.y - p.y;
        return dx * dx + dy * dy < r * r;
    };
    std::vector<Peak>& ranked = ranked_;  // at most areas x perArea
    ranked.clear();
    // With the prefilter, a ball's maximum may rank below dozens of line crossings: the whole
    // area is sorted (a few hundred maxima) and walked until perArea pass, at most
    // prefilterChecks of them tested (each test reads one ball square).
    const bool prefilter = prefilter_.active();
    for (auto& list : peaks_) {
        const std::size_t considered =
            prefilter ? list.size() : std::min<std::size_t>(list.size(), std::size_t(perArea) * 16);
        std::partial_sort(list.begin(), list.begin() + std::ptrdiff_t(considered), list.end(), stronger);
        const std::size_t areaStart = ranked.size();
        int rank = 0;
        int checks = 0;
        int listed = 0;  // refusals of this area listed (the strongest perArea)
        for (std::size_t i = 0; i < considered && rank < perArea; ++i) {
            bool suppressed = false;
            for (std::size_t k = areaStart; k < ranked.size() && !suppressed; ++k)
                suppressed = suppresses(ranked[k], list[i]);
            if (suppressed) continue;
            if (prefilter) {
                if (checks++ >= options_.prefilterChecks) break;
                if (!passesPrefilter(binary, list[i].x, list[i].y, list[i].sum, CandidateSource::SpecificHough,
                                     listed < perArea)) {
                    ++listed;
                    continue;
                }
            }
            Peak p = list[i];
            p.rank = rank++;
            ranked.push_back(p);
        }
    }
    // Across areas (a ball on an area bound): the weaker of two close maxima goes.
    std::sort(ranked.begin(), ranked.end(), stronger);
    kept_.clear();
    for (const Peak& r : ranked) {
        bool suppressed = false;
        for (std::size_t k = 0; k < kept_.size() && !suppressed; ++k) suppressed = suppresses(kept_[k], r);
        if (!suppressed) kept_.push_back(r);
    }
    // Candidates: every area's strongest, then every area's second, ... up to the cap.
    for (int rank = 0; rank < perArea; ++rank)
        for (std::size_t i = 0; i < kept_.size(); ++i) {
            if (kept_[i].rank != rank) continue;
            if (int(best_.size()) >= cap) return;
            best_.push_back(candidateAt(kept_[i].x, kept_[i].y, kept_[i].sum, CandidateSource::SpecificHough));
        }
}

}  // namespace omnitune
