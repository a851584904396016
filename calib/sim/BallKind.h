#pragma once
// The five balls of the thesis' experiments (ch. 5: balls 1..5) and what their surface looks
// like, so the simulator can paint them and tools can name them on the command line.
#include <opencv2/core.hpp>

#include <array>
#include <optional>
#include <string_view>

namespace omnitune {

enum class BallKind {
    Orange,           // ball 1: completely orange, the classic MSL ball
    MostlyBlack,      // ball 2: black panels on about 40 % of the surface, the rest white/grey
    WhiteBlackGreen,  // ball 3: white hexagons, black pentagons, a few small green patches
    MostlyBlue,       // ball 4: blue (not team cyan) hexagons, white pentagons
    WhiteRed,         // ball 5: white with red panels
    // Not in the thesis; balls teams meet today (issue 9).
    GreenWhite,       // white hexagons, green pentagons and every third hexagon green (~45 % green)
    YellowWhite,      // yellow hexagons, white pentagons (a yellow ball, hue ~27: not orange)
};

inline constexpr std::array<BallKind, 5> kAllBallKinds = {
    BallKind::Orange, BallKind::MostlyBlack, BallKind::WhiteBlackGreen, BallKind::MostlyBlue,
    BallKind::WhiteRed};

// The thesis' five (in thesis order, kAllBallKinds) plus the two newer balls, for the optics
// simulator's cells.
inline constexpr std::array<BallKind, 7> kExtendedBallKinds = {
    BallKind::Orange, BallKind::MostlyBlack, BallKind::WhiteBlackGreen, BallKind::MostlyBlue,
    BallKind::WhiteRed, BallKind::GreenWhite, BallKind::YellowWhite};

// "orange", "black", "white-black-green", "blue", "white-red", "green-white", "yellow-white".
std::string_view ballKindName(BallKind kind);
// Accepts the names above and the thesis' ball numbers "1".."5" (the two newer balls have no
// number); nullopt for anything else.
std::optional<BallKind> parseBallKind(std::string_view text);

// Unlit surface colour (BGR, 0..255) at unit vector `n` in the ball's own frame. The panels are
// a spherical truncated icosahedron (12 pentagons, 20 hexagons) with darker seams.
cv::Vec3f ballSurfaceColor(BallKind kind, const cv::Vec3d& n);

}  // namespace omnitune
