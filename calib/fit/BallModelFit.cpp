#include "calib/fit/BallModelFit.h"

#include "calib/fit/FitText.h"
#include "calib/fit/Polynomial.h"
#include "calib/fit/Residuals.h"
#include "core/Pi.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace omnitune {

std::vector<BallSample> ballSamplesFromTruth(const std::map<int, TruthRow>& truth, cv::Point2d centre)
{
    std::vector<BallSample> samples;
    for (const auto& [frame, row] : truth)
        if (row.ballVisible && row.radiusPx > 0)
            samples.push_back({std::hypot(row.px - centre.x, row.py - centre.y), row.radiusPx, frame,
                               std::atan2(row.py - centre.y, row.px - centre.x)});
    return samples;
}

std::vector<BallSample> ballSamplesFromDetections(const std::vector<FrameOutcome>& outcomes, cv::Point2d centre,
                                                  const std::map<int, TruthRow>& truth)
{
    std::vector<BallSample> samples;
    for (const FrameOutcome& o : outcomes) {
        const BallDetection& d = o.detection;
        if (o.processed && d.found && d.radiusPx > 0 && !truth.count(o.frame))
            samples.push_back({std::hypot(d.px - centre.x, d.py - centre.y), d.radiusPx, o.frame,
                               std::atan2(d.py - centre.y, d.px - centre.x)});
    }
    return samples;
}

namespace {

// Widest gap (deg) between the angles of the samples that have one.
double widestGapDeg(const std::vector<BallSample>& samples)
{
    std::vector<double> a;
    for (const BallSample& s : samples)
        if (s.angleRad) a.push_back(std::remainder(*s.angleRad, 2 * kPi) * 180 / kPi);
    if (a.size() < 2) return 360.0;
    std::sort(a.begin(), a.end());
    double gap = a.front() + 360 - a.back();
    for (std::size_t i = 1; i < a.size(); ++i) gap = std::max(gap, a[i] - a[i - 1]);
    return gap;
}

// r = p(d) * (1 + u cos a + v sin a), alternating two linear fits: p on r / (1 + ...), then
// (u, v) on r / p(d) - 1. Samples without an angle count with the factor 1.
BallModelFit::Direction fitDirection(const std::vector<BallSample>& samples)
{
    BallModelFit::Direction dir;
    std::vector<double> d, scaled;
    for (int round = 0; round < 8; ++round) {
        d.clear();
        scaled.clear();
        for (const BallSample& s : samples) {
            const double f = s.angleRad ? 1.0 + dir.cosTerm * std::cos(*s.angleRad) + dir.sinTerm * std::sin(*s.angleRad) : 1.0;
            d.push_back(s.distancePx);
            scaled.push_back(s.radiusPx / f);
        }
        const std::vector<double> c = fitPolynomial(d, scaled, 2);
        dir.c0 = c[0];
        dir.c1 = c[1];
        dir.c2 = c[2];
        // 2x2 normal equations of q = u cos a + v sin a.
        double cc = 0, cs = 0, ss = 0, qc = 0, qs = 0;
        for (const BallSample& s : samples) {
            if (!s.angleRad) continue;
            const double p = dir.c0 + dir.c1 * s.distancePx + dir.c2 * s.distancePx * s.distancePx;
            if (!(p > 0)) continue;
            const double q = s.radiusPx / p - 1, ca = std::cos(*s.angleRad), sa = std::sin(*s.angleRad);
            cc += ca * ca;
            cs += ca * sa;
            ss += sa * sa;
            qc += q * ca;
            qs += q * sa;
        }
        const double det = cc * ss - cs * cs;
        if (!(std::abs(det) > 1e-9)) break;
        dir.cosTerm = (qc * ss - qs * cs) / det;
        dir.sinTerm = (qs * cc - qc * cs) / det;
    }
    for (const BallSample& s : samples) {
        const double p = dir.c0 + dir.c1 * s.distancePx + dir.c2 * s.distancePx * s.distancePx;
        dir.residualsPx.push_back(s.radiusPx - (s.angleRad ? dir.radiusAt(s.distancePx, *s.angleRad) : p));
    }
    dir.rmsPx = rootMeanSquare(dir.residualsPx);
    return dir;
}

}  // namespace

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

    // The per-direction term, offered only when the residuals show it.
    const auto withAngle = std::count_if(samples.begin(), samples.end(), [](const BallSample& s) { return bool(s.angleRad); });
    const double gap = widestGapDeg(samples);
    if (withAngle < options.minDirectionSamples) {
        fit.directionNote = "no per-direction term: " + std::to_string(withAngle) + " samples with a direction, " +
                            std::to_string(options.minDirectionSamples) + " needed";
    } else if (gap > options.maxDirectionGapDeg) {
        fit.directionNote = "no per-direction term: the samples leave a " + fixedText(gap) + " deg gap around the centre";
    } else {
        fit.direction = fitDirection(samples);
        const BallModelFit::Direction& dir = *fit.direction;
        const double gain = fit.rmsPx > 0 ? 1.0 - dir.rmsPx / fit.rmsPx : 0.0;
        fit.directionOffered = dir.amplitude() >= options.minDirectionAmplitude && gain >= options.minDirectionRmsGain;
        fit.directionNote = std::string(fit.directionOffered ? "per-direction term offered" : "no per-direction term needed") +
                            ": the ball is " + fixedText(100 * dir.amplitude()) + " % bigger on one side (at " +
                            fixedText(std::atan2(dir.sinTerm, dir.cosTerm) * 180 / kPi) + " deg), RMS " +
                            fixedText(fit.rmsPx) + " -> " + fixedText(dir.rmsPx) + " px with it";
    }
    return result;
}

namespace {

// The clamp of r(d) must not cut what was measured: a camera whose nearest balls look bigger
// than ball.max_radius (25 px, the thesis' camera) gets a bound that holds the fitted curve
// over the samples' span, in its largest direction. It is only ever raised.
void holdMeasuredRadii(const BallModelFit& fit, BallModelOptions& ball)
{
    constexpr int kSteps = 16;  // points along the span; r(d) is a parabola, its ends and middle
    const double widest = 1.0 + std::hypot(ball.directionCos, ball.directionSin);
    double largest = 0.0;
    for (int i = 0; i <= kSteps; ++i) {
        const double d = fit.minDistancePx + (fit.maxDistancePx - fit.minDistancePx) * i / kSteps;
        largest = std::max(largest, (ball.c0 + ball.c1 * d + ball.c2 * d * d) * widest);
    }
    if (largest > ball.maxRadius) ball.maxRadius = std::ceil(largest);
}

}  // namespace

void applyBallModelFit(const BallModelFit& fit, BallModelOptions& ball, bool withDirection)
{
    if (withDirection && fit.direction) {
        const BallModelFit::Direction& dir = *fit.direction;
        ball.c0 = dir.c0;
        ball.c1 = dir.c1;
        ball.c2 = dir.c2;
        ball.directionCos = dir.cosTerm;
        ball.directionSin = dir.sinTerm;
    } else {
        ball.c0 = fit.c0;
        ball.c1 = fit.c1;
        ball.c2 = fit.c2;
        ball.directionCos = 0.0;
        ball.directionSin = 0.0;
    }
    holdMeasuredRadii(fit, ball);
}

}  // namespace omnitune
