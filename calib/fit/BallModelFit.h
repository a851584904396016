#pragma once
// The expected ball radius r(d) = c0 + c1*d + c2*d^2 (core/BallModel.h, thesis Fig. 4.7) from
// samples of the ball as seen: image distance of its centre from the mirror centre and its
// radius, both px. The samples come from ground-truth marks (a session's truth.csv) and from
// accepted detections (a whole-session run).
#include "calib/eval/Evaluation.h"
#include "calib/fit/FitError.h"
#include "calib/session/TruthCsv.h"
#include "core/BallModel.h"

#include <opencv2/core.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct BallSample {
    double distancePx = 0.0;  // ball centre's image distance from the mirror centre
    double radiusPx = 0.0;    // the ball's radius as seen
    int frame = -1;           // where it was marked, -1 when unknown
    std::optional<double> angleRad = std::nullopt;  // image angle of the centre about the mirror centre (atan2(dy, dx)), when known
};

struct BallModelFitOptions {
    int minSamples = 6;         // three coefficients; twice that many samples keeps one mark from ruling
    double minSpanPx = 40.0;    // px the samples' distances must span, or the curve is a guess outside them
    // The per-direction term (an off-axis mirror) is offered when it is this large, takes this
    // share off the RMS and the samples with an angle cover the circle this well.
    double minDirectionAmplitude = 0.03;  // ratio: 3 % bigger on one side than on average
    double minDirectionRmsGain = 0.2;     // share of the radial fit's RMS the term removes
    int minDirectionSamples = 12;         // samples with an angle
    double maxDirectionGapDeg = 120.0;    // deg: the widest gap between their angles
};

struct BallModelFit {
    double c0 = 0.0, c1 = 0.0, c2 = 0.0;  // BallModelOptions' coefficients
    double minDistancePx = 0.0;           // span of the samples
    double maxDistancePx = 0.0;
    std::vector<double> residualsPx;      // per sample, seen minus fitted
    double rmsPx = 0.0;
    double maxAbsPx = 0.0;
    int worstSample = -1;                 // index of the sample with the largest residual

    double radiusAt(double distancePx) const { return c0 + c1 * distancePx + c2 * distancePx * distancePx; }

    // The same samples fitted with the per-direction term r(d) * (1 + cos*cos(a) + sin*sin(a))
    // (core/BallModel.h), when enough samples have an angle; `directionOffered` when the
    // residuals show it (BallModelFitOptions). Its own radial coefficients, fitted jointly.
    struct Direction {
        double c0 = 0.0, c1 = 0.0, c2 = 0.0;
        double cosTerm = 0.0, sinTerm = 0.0;
        std::vector<double> residualsPx;  // per sample, seen minus fitted
        double rmsPx = 0.0;
        double amplitude() const { return std::hypot(cosTerm, sinTerm); }
        double radiusAt(double distancePx, double angleRad) const
        {
            return (c0 + c1 * distancePx + c2 * distancePx * distancePx) *
                   (1.0 + cosTerm * std::cos(angleRad) + sinTerm * std::sin(angleRad));
        }
    };
    std::optional<Direction> direction;  // fitted when possible
    bool directionOffered = false;
    std::string directionNote;           // why it is or is not offered, in words
};

struct BallModelFitResult {
    BallModelFit fit;  // meaningful only when ok()
    std::optional<FitError> error;

    bool ok() const { return !error.has_value(); }
};

// The visible balls of the truth rows, measured from `centre`.
std::vector<BallSample> ballSamplesFromTruth(const std::map<int, TruthRow>& truth, cv::Point2d centre);

// The balls `outcomes` found, measured from `centre`, leaving out the frames in `truth` (their
// marks are the better sample of the same ball).
std::vector<BallSample> ballSamplesFromDetections(const std::vector<FrameOutcome>& outcomes, cv::Point2d centre,
                                                  const std::map<int, TruthRow>& truth = {});

BallModelFitResult fitBallModel(const std::vector<BallSample>& samples, const BallModelFitOptions& options = {});

// Writes c0, c1, c2 and the per-direction terms (0 and 0, or the direction fit's with its own
// coefficients when `withDirection` and the fit has one); the clamps and the square ratio stay.
void applyBallModelFit(const BallModelFit& fit, BallModelOptions& ball, bool withDirection = false);

}  // namespace omnitune
