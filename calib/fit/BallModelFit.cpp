#include "calib/fit/BallModelFit.h"

#include "calib/fit/FitText.h"
#include "calib/fit/Polynomial.h"
#include "calib/fit/Residuals.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace omnitune {

std::vector<BallSample> ballSamplesFromTruth(const std::map<int, TruthRow>& truth, cv::Point2d centre)
{
    std::vector<BallSample> samples;
    for (const auto& [frame, row] : truth)
        if (row.ballVisible && row.radiusPx > 0)
            samples.push_back({std::hypot(row.px - centre.x, row.py - centre.y), row.radiusPx, frame});
    return samples;
}

std::vector<BallSample> ballSamplesFromDetections(const std::vector<FrameOutcome>& outcomes, cv::Point2d centre,
                                                  const std::map<int, TruthRow>& truth)
{
    std::vector<BallSample> samples;
    for (const FrameOutcome& o : outcomes) {
        const BallDetection& d = o.detection;
        if (o.processed && d.found && d.radiusPx > 0 && !truth.count(o.frame))
            samples.push_back({std::hypot(d.px - centre.x, d.py - centre.y), d.radiusPx, o.frame});
    }
    return samples;
}

BallModelFitResult fitBallModel(const std::vector<BallSample>& samples, const BallModelFitOptions& options)
{
    BallModelFitResult result;
    if (int(samples.size()) < std::max(3, options.minSamples)) {
        result.error = FitError{FitErrorKind::TooFewPoints,
                                "the ball model needs at least " + std::to_string(std::max(3, options.minSamples)) +
                                    " marked balls (got " + std::to_string(samples.size()) +
                                    "); mark the ball in more frames, near and far"};
        return result;
    }
    std::vector<double> d, r;
    for (const auto& s : samples) {
        if (!(s.radiusPx > 0) || !(s.distancePx >= 0) || !std::isfinite(s.radiusPx) || !std::isfinite(s.distancePx)) {
            result.error = FitError{FitErrorKind::BadInput, "a ball sample" +
                                                                (s.frame >= 0 ? " (frame " + std::to_string(s.frame) + ")" : std::string()) +
                                                                " has a non-positive radius or a bad distance"};
            return result;
        }
        d.push_back(s.distancePx);
        r.push_back(s.radiusPx);
    }
    BallModelFit& fit = result.fit;
    fit.minDistancePx = *std::min_element(d.begin(), d.end());
    fit.maxDistancePx = *std::max_element(d.begin(), d.end());
    if (fit.maxDistancePx - fit.minDistancePx < options.minSpanPx) {
        result.error = FitError{FitErrorKind::NarrowSpan,
                                "the marked balls lie between " + fixedText(fit.minDistancePx) + " and " +
                                    fixedText(fit.maxDistancePx) + " px from the centre, less than " + fixedText(options.minSpanPx) +
                                    " px apart; mark balls both near the robot and far away"};
        return result;
    }
    const std::vector<double> c = fitPolynomial(d, r, 2);
    fit.c0 = c[0];
    fit.c1 = c[1];
    fit.c2 = c[2];
    // A curve that reaches zero inside the span is no ball radius: the marks contradict each other.
    for (int i = 0; i <= 100; ++i) {
        const double at = fit.minDistancePx + (fit.maxDistancePx - fit.minDistancePx) * i / 100;
        if (fit.radiusAt(at) <= 0) {
            result.error = FitError{FitErrorKind::OutOfRange, "the fitted ball radius falls to zero at " + fixedText(at) +
                                                                  " px; check the marks around there"};
            return result;
        }
    }
    for (std::size_t i = 0; i < samples.size(); ++i) fit.residualsPx.push_back(r[i] - fit.radiusAt(d[i]));
    fit.rmsPx = rootMeanSquare(fit.residualsPx);
    fit.maxAbsPx = maxAbsolute(fit.residualsPx);
    for (std::size_t i = 0; i < fit.residualsPx.size(); ++i)
        if (fit.worstSample < 0 && std::abs(fit.residualsPx[i]) == fit.maxAbsPx) fit.worstSample = int(i);
    return result;
}

void applyBallModelFit(const BallModelFit& fit, BallModelOptions& ball)
{
    ball.c0 = fit.c0;
    ball.c1 = fit.c1;
    ball.c2 = fit.c2;
}

}  // namespace omnitune
