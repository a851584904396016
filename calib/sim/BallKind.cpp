#include "calib/sim/BallKind.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace omnitune {

namespace {

// Panel centres of a truncated icosahedron: pentagons at the icosahedron's 12 vertices,
// hexagons at its 20 face centres (the dodecahedron's vertices).
struct PanelCentres {
    std::vector<cv::Vec3d> pentagons;
    std::vector<cv::Vec3d> hexagons;

    PanelCentres()
    {
        const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
        for (double a : {-1.0, 1.0})
            for (double b : {-phi, phi}) {
                pentagons.push_back(cv::normalize(cv::Vec3d(0, a, b)));
                pentagons.push_back(cv::normalize(cv::Vec3d(a, b, 0)));
                pentagons.push_back(cv::normalize(cv::Vec3d(b, 0, a)));
            }
        for (double a : {-1.0, 1.0})
            for (double b : {-1.0, 1.0}) {
                for (double c : {-1.0, 1.0}) hexagons.push_back(cv::normalize(cv::Vec3d(a, b, c)));
                hexagons.push_back(cv::normalize(cv::Vec3d(0, a / phi, b * phi)));
                hexagons.push_back(cv::normalize(cv::Vec3d(a / phi, b * phi, 0)));
                hexagons.push_back(cv::normalize(cv::Vec3d(b * phi, 0, a / phi)));
            }
    }
};

const PanelCentres& panelCentres()
{
    static const PanelCentres centres;
    return centres;
}

struct Panel {
    bool pentagon = false;
    int index = 0;       // into pentagons or hexagons
    double fromCentre = 0; // rad, angle to the panel's centre
    double toEdge = 0;   // rad, about the angle to the nearest panel boundary
};

// Which panel holds `n`. `pentagonGrowth` (rad) moves every pentagon-hexagon boundary away
// from the pentagon: 0 is the plain Voronoi split (pentagons 31 % of the sphere); -0.038 puts
// it where a real ball's seam is (16.5 deg from the pentagon centre; pentagons 26 %).
Panel findPanel(const cv::Vec3d& n, double pentagonGrowth)
{
    const PanelCentres& c = panelCentres();
    int bestP = 0;
    double dotP = -2;
    for (std::size_t i = 0; i < c.pentagons.size(); ++i) {
        const double d = n.dot(c.pentagons[i]);
        if (d > dotP) dotP = d, bestP = int(i);
    }
    int bestH = 0;
    double dotH = -2;
    double dotH2 = -2;
    for (std::size_t i = 0; i < c.hexagons.size(); ++i) {
        const double d = n.dot(c.hexagons[i]);
        if (d > dotH) dotH2 = dotH, dotH = d, bestH = int(i);
        else if (d > dotH2) dotH2 = d;
    }
    const auto angle = [](double d) { return std::acos(std::clamp(d, -1.0, 1.0)); };
    const double angP = angle(dotP) - pentagonGrowth;
    const double angH = angle(dotH);
    Panel p;
    if (angP < angH) {
        p.pentagon = true;
        p.index = bestP;
        p.fromCentre = angle(dotP);
        p.toEdge = 0.5 * (angH - angP);
    } else {
        p.index = bestH;
        p.fromCentre = angH;
        p.toEdge = 0.5 * std::min(angle(dotH2) - angH, angP - angH);
    }
    return p;
}

// Colours (BGR). Each is picked for what the default colour LUT makes of it (core/ColorLut.cpp):
// white panels stay above the black class' value bound even shaded, blue has hue ~113 (outside
// the cyan marker range 86..105), red hue ~176 (outside orange 5..22).
const cv::Vec3f kOrange(32, 111, 230);     // HSV ~ (12, 220, 230)
const cv::Vec3f kBallWhite(232, 232, 228);
const cv::Vec3f kBallGrey(200, 200, 196);
const cv::Vec3f kBallBlack(28, 28, 30);
const cv::Vec3f kBallGreen(50, 160, 45);
const cv::Vec3f kBallBlue(200, 72, 30);
const cv::Vec3f kBallRed(45, 30, 200);
const cv::Vec3f kBallFieldGreen(55, 165, 50);  // close to the carpet: the hard case of issue 9
const cv::Vec3f kBallYellow(30, 205, 235);     // HSV ~ (27, 222, 235): above the orange hue range

// Seams are thin grooves; they darken the surface a little without changing its class.
constexpr double kSeamHalfWidth = 0.012;  // rad
constexpr float kSeamShade = 0.8f;

// The hexagons of the white-black-green ball that carry a small green patch: spread over the
// sphere so a few are usually in view, each a cap of kGreenPatchRadius (~0.6 % of the surface).
constexpr std::array<int, 4> kGreenHexagons = {0, 6, 13, 19};
constexpr double kGreenPatchRadius = 0.15;  // rad

}  // namespace

std::string_view ballKindName(BallKind kind)
{
    switch (kind) {
    case BallKind::Orange: return "orange";
    case BallKind::MostlyBlack: return "black";
    case BallKind::WhiteBlackGreen: return "white-black-green";
    case BallKind::MostlyBlue: return "blue";
    case BallKind::WhiteRed: return "white-red";
    case BallKind::GreenWhite: return "green-white";
    case BallKind::YellowWhite: return "yellow-white";
    }
    return "orange";
}

std::optional<BallKind> parseBallKind(std::string_view text)
{
    constexpr std::string_view thesisNumbers = "12345";  // kAllBallKinds is in thesis order
    for (std::size_t i = 0; i < kAllBallKinds.size(); ++i) {
        const BallKind k = kAllBallKinds[i];
        if (text == ballKindName(k) || text == thesisNumbers.substr(i, 1)) return k;
    }
    for (BallKind k : {BallKind::GreenWhite, BallKind::YellowWhite})
        if (text == ballKindName(k)) return k;
    return std::nullopt;
}

cv::Vec3f ballSurfaceColor(BallKind kind, const cv::Vec3d& n)
{
    // MostlyBlack grows its black pentagons to 40 % of the surface (so the non-black test still
    // sees > 50 %); the others use the real ball's proportions.
    const double growth = kind == BallKind::MostlyBlack ? 0.045 : -0.038;
    const Panel p = findPanel(n, growth);
    cv::Vec3f c;
    switch (kind) {
    case BallKind::Orange: c = kOrange; break;
    case BallKind::MostlyBlack: c = p.pentagon ? kBallBlack : (p.index % 2 ? kBallWhite : kBallGrey); break;
    case BallKind::WhiteBlackGreen:
        c = p.pentagon ? kBallBlack : kBallWhite;
        if (!p.pentagon && p.fromCentre < kGreenPatchRadius &&
            std::find(kGreenHexagons.begin(), kGreenHexagons.end(), p.index) != kGreenHexagons.end())
            c = kBallGreen;
        break;
    case BallKind::MostlyBlue: c = p.pentagon ? kBallWhite : kBallBlue; break;
    case BallKind::WhiteRed: c = p.pentagon ? kBallRed : kBallWhite; break;
    case BallKind::GreenWhite: c = p.pentagon || p.index % 3 == 0 ? kBallFieldGreen : kBallWhite; break;
    case BallKind::YellowWhite: c = p.pentagon ? kBallWhite : kBallYellow; break;
    }
    if (p.toEdge < kSeamHalfWidth) c *= kSeamShade;
    return c;
}

}  // namespace omnitune
