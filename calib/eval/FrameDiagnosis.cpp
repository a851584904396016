#include "calib/eval/FrameDiagnosis.h"

#include "core/Validation.h"

#include <algorithm>
#include <cmath>

namespace omnitune {

std::string_view missCauseName(MissCause cause)
{
    switch (cause) {
    case MissCause::NoCandidate: return "no candidate";
    case MissCause::TooSmall: return "too small";
    case MissCause::OutOfRange: return "out of area/radius";
    case MissCause::NonGreen: return "non-green";
    case MissCause::NonBlack: return "non-black";
    case MissCause::Circularity: return "circularity";
    case MissCause::CircleOff: return "circle off model";
    case MissCause::RunsOn: return "runs on";
    case MissCause::LostToOther: return "lost to another";
    case MissCause::PositionOff: return "position off";
    }
    return "?";
}

std::string_view falsePositivePlaceName(FalsePositivePlace place)
{
    switch (place) {
    case FalsePositivePlace::Rim: return "rim";
    case FalsePositivePlace::Mask: return "mask";
    case FalsePositivePlace::Body: return "body";
    case FalsePositivePlace::Field: return "field";
    }
    return "?";
}

std::size_t falsePositiveKindIndex(FalsePositiveKind kind)
{
    return std::size_t(kind.source) * kFalsePositivePlaceCount + std::size_t(kind.place);
}

FalsePositiveKind falsePositiveKindAt(std::size_t index)
{
    return {CandidateSource(index / kFalsePositivePlaceCount), FalsePositivePlace(index % kFalsePositivePlaceCount)};
}

namespace {

// How far a candidate got through validation, in the order the tests run; higher is farther.
int progressOf(const BallCandidate& c, const ValidationOptions& v)
{
    switch (c.rejected) {
    case RejectReason::OutsideArea:
    case RejectReason::RadiusTooLarge: return 0;
    case RejectReason::TooSmall: return 1;
    case RejectReason::NonGreen: return 2;
    case RejectReason::NonBlack: return 3;
    case RejectReason::Circularity: return c.scores.circularityPct >= requiredCircularityPct(c, v) ? 5 : 4;
    case RejectReason::RunsOn:
    case RejectReason::LineJunction:
    case RejectReason::LineBlob: return 6;  // the last shape tests: a miss there "runs on"
    case RejectReason::NotChosen: return 7;
    case RejectReason::None: return 8;
    }
    return 0;
}

MissCause causeOf(int progress)
{
    constexpr MissCause kByProgress[] = {MissCause::OutOfRange,  MissCause::TooSmall,  MissCause::NonGreen,
                                         MissCause::NonBlack,    MissCause::Circularity, MissCause::CircleOff,
                                         MissCause::RunsOn,      MissCause::LostToOther, MissCause::PositionOff};
    return kByProgress[std::clamp(progress, 0, int(std::size(kByProgress)) - 1)];
}

}  // namespace

const BallCandidate* candidateAtBall(const PipelineResult& result, const TruthRow& truth,
                                     const ValidationOptions& validation)
{
    const double near = std::max(truth.radiusPx, 2.0);
    const BallCandidate* best = nullptr;
    for (const BallCandidate& c : result.candidates) {
        if (std::hypot(c.x - truth.px, c.y - truth.py) > near) continue;
        if (!best || progressOf(c, validation) > progressOf(*best, validation)) best = &c;
    }
    return best;
}

MissCause diagnoseMiss(const PipelineResult& result, const TruthRow& truth, const ValidationOptions& validation,
                       bool* radiusOff, const BallCandidate** atBall)
{
    if (radiusOff) *radiusOff = false;
    const BallCandidate* best = candidateAtBall(result, truth, validation);
    if (atBall) *atBall = best;
    if (!best) return MissCause::NoCandidate;
    if (radiusOff) {
        const double allowance = fitAllowance(best->expectedRadiusPx, validation);
        *radiusOff = std::abs(truth.radiusPx - best->expectedRadiusPx) > allowance;
    }
    return causeOf(progressOf(*best, validation));
}

FalsePositiveKind diagnoseFalsePositive(const PipelineResult& result, const Config& config)
{
    FalsePositiveKind kind;
    const BallDetection& d = result.detection;
    if (d.candidate >= 0 && d.candidate < int(result.candidates.size()))
        kind.source = result.candidates[std::size_t(d.candidate)].source;
    const GeometryOptions& g = config.geometry;
    // The circle as validation saw it, and the blurred pixel beyond.
    const double reach = d.radiusPx + 2.0;
    const double r = std::hypot(d.px - g.centerX, d.py - g.centerY);
    if (r + reach >= g.outerRadius) {
        kind.place = FalsePositivePlace::Rim;
        return kind;
    }
    if (r - reach <= g.innerRadius) {
        kind.place = FalsePositivePlace::Body;
        return kind;
    }
    const cv::Mat& mask = config.mask;
    if (!mask.empty()) {
        const int x0 = std::max(0, int(std::floor(d.px - reach)));
        const int x1 = std::min(mask.cols - 1, int(std::ceil(d.px + reach)));
        const int y0 = std::max(0, int(std::floor(d.py - reach)));
        const int y1 = std::min(mask.rows - 1, int(std::ceil(d.py + reach)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                if (mask.at<std::uint8_t>(y, x) == 0 && std::hypot(x - d.px, y - d.py) <= reach) {
                    kind.place = FalsePositivePlace::Mask;
                    return kind;
                }
    }
    kind.place = FalsePositivePlace::Field;
    return kind;
}

}  // namespace omnitune
