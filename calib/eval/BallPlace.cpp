#include "calib/eval/BallPlace.h"

#include "calib/sim/FieldModel.h"
#include "calib/sim/RobotPose.h"

#include <cmath>

namespace omnitune {

const char* ballPlaceName(BallPlace place)
{
    switch (place) {
    case BallPlace::Under2m: return "range: under 2 m";
    case BallPlace::From2To3m: return "range: 2-3 m";
    case BallPlace::From3To4m: return "range: 3-4 m";
    case BallPlace::From4m: return "range: 4 m and more";
    case BallPlace::OutOfPlay: return "place: beyond the outer lines (out of play)";
    }
    return "?";
}

std::array<bool, kBallPlaceCount> ballPlacesOf(const TruthRow& truth, const FieldDimensions& field, double ballRadiusM)
{
    std::array<bool, kBallPlaceCount> places{};
    const double range = std::hypot(truth.xM, truth.yM);
    const BallPlace band = range < 2.0   ? BallPlace::Under2m
                           : range < 3.0 ? BallPlace::From2To3m
                           : range < 4.0 ? BallPlace::From3To4m
                                         : BallPlace::From4m;
    places[std::size_t(band)] = true;
    if (truth.robot) {
        // Out of play once wholly over the line: its nearest point past the line's outer edge.
        const cv::Point2d p = toFieldFrame(*truth.robot, {truth.xM, truth.yM});
        const double outerX = field.length / 2 + field.lineWidth / 2;
        const double outerY = field.width / 2 + field.lineWidth / 2;
        places[std::size_t(BallPlace::OutOfPlay)] =
            std::abs(p.x) - ballRadiusM > outerX || std::abs(p.y) - ballRadiusM > outerY;
    }
    return places;
}

}  // namespace omnitune
