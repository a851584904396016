#include "calib/fit/BodyFit.h"

#include "calib/fit/FitText.h"
#include "calib/fit/GrayFrames.h"
#include "calib/fit/Residuals.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace omnitune {

BodyFitResult fitBody(const std::vector<cv::Mat>& frames, cv::Point2d centre, double rimRadius,
                      const BodyFitOptions& options, Progress* progress)
{
    BodyFitResult result;
    if (int(frames.size()) < std::max(2, options.minFrames)) {
        result.error = FitError{FitErrorKind::TooFewFrames,
                                "the robot body needs at least " + std::to_string(std::max(2, options.minFrames)) +
                                    " frames (got " + std::to_string(frames.size()) +
                                    "); use more frames taken while the robot turns or drives"};
        return result;
    }
    std::vector<cv::Mat> gray;
    if (auto e = toGrayFrames(frames, gray)) {
        result.error = e;
        return result;
    }
    const cv::Size size = gray.front().size();
    if (!(rimRadius > 4)) {
        result.error = FitError{FitErrorKind::BadInput, "the rim radius " + fixedText(rimRadius) + " px is too small"};
        return result;
    }

    // Per-pixel variance over the frames (sum and sum of squares; grey levels are small).
    cv::Mat sum = cv::Mat::zeros(size, CV_64F);
    cv::Mat sumSq = cv::Mat::zeros(size, CV_64F);
    for (std::size_t i = 0; i < gray.size(); ++i) {
        if (progress && progress->isCancelRequested()) {
            result.error = FitError{FitErrorKind::Cancelled, "body fit cancelled"};
            return result;
        }
        cv::Mat g;
        gray[i].convertTo(g, CV_64F);
        sum += g;
        sumSq += g.mul(g);
        if (progress) progress->update(90.0 * double(i + 1) / double(gray.size()));
    }
    const double n = double(gray.size());

    // Averaged in rings of one pixel.
    const int rings = int(std::ceil(rimRadius));
    std::vector<double> ringSum(std::size_t(rings), 0.0);
    std::vector<int> ringCount(std::size_t(rings), 0);
    for (int y = 0; y < size.height; ++y) {
        const double* s = sum.ptr<double>(y);
        const double* q = sumSq.ptr<double>(y);
        for (int x = 0; x < size.width; ++x) {
            const int ring = int(std::hypot(x - centre.x, y - centre.y));
            if (ring >= rings) continue;
            const double mean = s[x] / n;
            ringSum[std::size_t(ring)] += std::max(0.0, q[x] / n - mean * mean);
            ++ringCount[std::size_t(ring)];
        }
    }
    BodyFit& fit = result.fit;
    fit.frames = int(gray.size());
    fit.ringVariance.assign(std::size_t(rings), 0.0);
    for (int r = 0; r < rings; ++r)
        if (ringCount[std::size_t(r)] > 0) fit.ringVariance[std::size_t(r)] = ringSum[std::size_t(r)] / ringCount[std::size_t(r)];

    // The field: the outer half of the mirror (always field). The body: the quietest stretch of
    // the inner half, from the centre out.
    std::vector<double> outer;
    for (int r = rings / 2; r < rings; ++r)
        if (ringCount[std::size_t(r)] > 0) outer.push_back(fit.ringVariance[std::size_t(r)]);
    fit.fieldLevel = median(outer);
    int quietest = 1;
    for (int r = 1; r < rings / 2; ++r)
        if (ringCount[std::size_t(r)] > 0 && fit.ringVariance[std::size_t(r)] < fit.ringVariance[std::size_t(quietest)])
            quietest = r;
    std::vector<double> body;
    for (int r = 1; r <= quietest; ++r)
        if (ringCount[std::size_t(r)] > 0) body.push_back(fit.ringVariance[std::size_t(r)]);
    fit.bodyLevel = median(body);
    if (!(fit.fieldLevel >= options.minFieldRatio * std::max(fit.bodyLevel, 0.25))) {
        result.error = FitError{FitErrorKind::StaticField,
                                "the field hardly changes between the frames (variance " + fixedText(fit.fieldLevel) +
                                    " over the field, " + fixedText(fit.bodyLevel) +
                                    " in the middle): use frames taken while the robot turns or drives, or set the "
                                    "inner radius by hand"};
        return result;
    }

    // Outwards from the quietest ring to where the variance rises past the level; the crossing
    // interpolated between the two rings (ring r holds radii r..r+1, its middle at r + 0.5).
    const double level = fit.bodyLevel + options.rise * (fit.fieldLevel - fit.bodyLevel);
    int r = quietest;
    while (r + 1 < rings / 2 && fit.ringVariance[std::size_t(r + 1)] < level) ++r;
    if (r + 1 >= rings / 2) {
        result.error = FitError{FitErrorKind::StaticField,
                                "no edge between a still body and a moving field inside half the rim radius; use "
                                "frames in which the field near the robot changes, or set the inner radius by hand"};
        return result;
    }
    const double a = fit.ringVariance[std::size_t(r)];
    const double b = fit.ringVariance[std::size_t(r + 1)];
    fit.bodyRadius = r + 0.5 + (level - a) / std::max(b - a, 1e-9);
    fit.innerRadius = fit.bodyRadius + options.marginPx;
    if (progress) progress->update(100.0);
    return result;
}

}  // namespace omnitune
