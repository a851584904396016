#pragma once
// The rules a ground-truth mark follows, apart from any window: a click marks the ball with
// the radius the ball model expects at that distance, a drag gives the radius by hand, and
// the detector's result can be taken as it is. A hand-set radius far outside what the ball
// model allows is most likely a slip (a drag meant to pan), so the window asks before it
// keeps one.
#include "calib/session/TruthCsv.h"
#include "core/PipelineResult.h"
#include "core/Config.h"

#include <optional>
#include <string>

namespace omnitune {

// "Far outside" the ball model: a radius above ball.max_radius times this factor or below
// ball.min_radius divided by it (with the thesis' 3-25 px: below 2 px or above 37.5 px). Wide
// enough that a ball marked by hand a little larger than the model (lens, a ball held
// higher) passes without a question.
inline constexpr double kMarkRadiusFarFactor = 1.5;

// Why `radiusPx` is far outside the ball model's range, or nothing when it is plausible.
std::optional<std::string> radiusFarFromModel(double radiusPx, const BallModelOptions& ball);

// A "ball at (x, y)" row for `frame` measured with `config` (world position through its
// distance map). `radiusPx` <= 0: the model's radius at that distance. `imageSize`: the
// frame's; the centre must lie inside it. Returns why not, or fills `out`.
std::optional<std::string> makeBallMark(const Config& config, cv::Size imageSize, int frame, double x, double y,
                                        double radiusPx, TruthRow& out);

// The detector's result as truth: its ball, or "no ball" when it found none.
TruthRow detectionMark(int frame, const BallDetection& detection);

}  // namespace omnitune
