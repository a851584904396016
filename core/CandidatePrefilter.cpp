#include "core/CandidatePrefilter.h"

#include "core/Config.h"

#include <algorithm>

namespace omnitune {

CandidatePrefilter candidatePrefilterFor(const Config& config)
{
    CandidatePrefilter p;
    const ValidationOptions& v = config.validation;
    // A known ball colour lets a candidate skip the non-green test: nothing to ask early then.
    const bool hinted = v.ballHint != "none";
    if (!hinted) {
        p.minNonGreenPct = config.hough.prefilterNonGreen * v.minNonGreenPct;
        p.minNonBlackPct = config.hough.prefilterNonBlack * v.minNonBlackPct;
    }
    p.roles = ColourRoles(config.colors.classes);
    p.validation = v;
    p.tooSmallBelowPx = v.minRadiusPx;
    // The rim test (validation.rim_test) judges circles up to rim_max_overhang_px farther out.
    if (config.hough.prefilterRim && v.refuseAtRim) {
        p.maxReachPx = config.geometry.outerRadius - v.rimMarginPx + (v.rimTest ? v.rimMaxOverhangPx : 0.0);
        p.rimTest = config.hough.prefilterRimTest && v.rimTest;
    }
    return p;
}

SquareShares classSquareShares(const cv::Mat& binary, const cv::Mat& classes, const cv::Mat& used,
                               const ColourRoles& roles, int x, int y, int side)
{
    const int half = side / 2;
    int processed = 0;
    int nonGreen = 0;
    int black = 0;
    const bool byClass = !classes.empty();
    for (int yy = std::max(0, y - half); yy <= std::min(binary.rows - 1, y + half); ++yy) {
        const std::uint8_t* b = binary.ptr<std::uint8_t>(yy);
        const std::uint8_t* u = used.ptr<std::uint8_t>(yy);
        const std::uint8_t* c = byClass ? classes.ptr<std::uint8_t>(yy) : nullptr;
        for (int xx = std::max(0, x - half); xx <= std::min(binary.cols - 1, x + half); ++xx) {
            if (!u[xx]) continue;
            ++processed;
            nonGreen += b[xx] != 255;
            black += byClass && roles.black(c[xx]);
        }
    }
    SquareShares s;
    if (processed > 0) {
        s.nonGreenPct = 100.0 * nonGreen / processed;
        s.nonBlackPct = 100.0 * (processed - black) / processed;
    }
    return s;
}

}  // namespace omnitune
