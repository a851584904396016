#include "core/Validation.h"

#include "core/BallEllipse.h"
#include "core/BallModel.h"
#include "core/ColorClass.h"
#include "core/ExpectedRadius.h"
#include "core/ForeignContact.h"
#include "core/FrameColour.h"
#include "core/Geometry.h"
#include "core/GreenPanelTest.h"
#include "core/HallRay.h"
#include "core/LineArms.h"
#include "core/LineContact.h"
#include "core/LineShare.h"
#include "core/RimTest.h"
#include "core/RoundHalfAway.h"
#include "core/SurroundContrast.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <optional>

namespace omnitune {

namespace {

// Circle search rays: about one per pixel of circumference, never fewer than 16.
int rayCount(double radius) { return std::max(16, int(std::ceil(2.0 * M_PI * radius))); }

// The circle being scored and the images it is scored on.
struct Circle {
    int x;
    int y;
    double radius;
    const cv::Mat& classes;
    const cv::Mat& edges;
    const Geometry& geometry;
    const ValidationOptions& options;
    const FrameColour* colour;  // null: colours unknown, every green pixel is carpet
    const ColourRoles& roles;   // "green": a field class, "black": a black class
    ColorClass hint;            // options.ballHint's id, Unknown: no hint
    CarpetColour carpet;        // measured around the circle when carpetByColour
    const EnclosedPanels* panels = nullptr;  // greenPanels: the ball's enclosed green panels
    // The ball's ellipse (radialSquash): radial over tangential semi-axis, and the unit radial
    // direction (from the mirror centre through the candidate). 1: a circle.
    double squash = 1.0;
    cv::Point2d radial{1.0, 0.0};
    ColorClass ballClass = ColorClass::Unknown;  // foreignRaysUnknown: the centre's ball class

    // How far out the ellipse of area-equivalent radius 1 reaches in the direction (ca, sa).
    double reachAlong(double ca, double sa) const
    {
        if (squash == 1.0) return 1.0;
        const double cr = ca * radial.x + sa * radial.y;  // along the radial axis
        const double ct = sa * radial.x - ca * radial.y;  // along the tangential one
        return squashedReach(cr, ct, squash);
    }
    // A border point (relative to the centre) in the circle's space: the ellipse onto the
    // circle of the same area, so that the circle fit and its allowances apply unchanged.
    cv::Point2d unsquash(cv::Point2d p) const
    {
        if (squash == 1.0) return p;
        const double s = std::sqrt(squash);
        const double pr = (p.x * radial.x + p.y * radial.y) / s;
        const double pt = (p.y * radial.x - p.x * radial.y) * s;
        return {pr * radial.x - pt * radial.y, pr * radial.y + pt * radial.x};
    }

    // A class of a robot hiding the ball: black, or (markerRaysUnknown) a team marker.
    bool robotAt(std::uint8_t cls) const { return roles.black(cls) || (options.markerRaysUnknown && roles.marker(cls)); }
    bool byColour() const { return colour && options.carpetByColour && carpet.valid(); }
    // A black-class pixel dark against the carpet around the candidate (blackByLocalCarpet).
    bool blackAt(cv::Point p) const
    {
        if (!roles.black(classAt(p))) return false;
        if (!colour || !options.blackByLocalCarpet || !carpet.valid()) return true;
        return colour->hsvAt(p.x, p.y).v <= options.localBlackVRatio * carpet.value();
    }
    // Inside the image and processed: its class and edge say something about the scene.
    bool known(cv::Point p) const
    {
        return p.x >= 0 && p.y >= 0 && p.x < classes.cols && p.y < classes.rows && geometry.isUsed(p.x, p.y);
    }
    std::uint8_t classAt(cv::Point p) const { return classes.ptr<std::uint8_t>(p.y)[p.x]; }
    bool edgeAt(cv::Point p) const { return edges.ptr<std::uint8_t>(p.y)[p.x] != 0; }
    // A known pixel of the carpet: green, not an enclosed panel of the ball (greenPanels), and
    // (carpetByColour) of the carpet's own green.
    bool carpetAt(cv::Point p) const
    {
        // Not a green panel enclosed by the ball's white; the colour first, as the panel walk is
        // the costly part of validation and only carpet-coloured pixels need it.
        return carpetColourAt(p) && !(panels && panels->at(p));
    }
    // The same by colour alone (every green panel of the carpet's colour is carpet).
    bool carpetColourAt(cv::Point p) const
    {
        if (!roles.field(classAt(p))) return false;
        return !byColour() || carpet.matches(colour->hsvAt(p.x, p.y), options.carpetTolerance);
    }
    // Darker than the carpet around by squareShadeTolerance: a carpet-coloured pixel of the
    // ball's shaded side (the square's tests only; needs byColour()).
    bool shadedAt(cv::Point p) const
    {
        return carpet.darker(colour->hsvAt(p.x, p.y).v, options.squareShadeTolerance, options.carpetTolerance.sigmas);
    }
    // Carpet lies a little farther out than beyondEdgePx: the border's blend of ball and carpet
    // colours (motion blur, optics) is green by class but not the carpet's green yet.
    bool carpetFollows(double r, double ca, double sa) const
    {
        for (double d = 1.0; d <= options.borderBlendPx + 1e-9; d += 1.0) {
            const cv::Point p = along(r + options.beyondEdgePx + d, ca, sa);
            if (!known(p)) return true;
            if (carpetAt(p)) return true;
        }
        return false;
    }
    // Green class but not the carpet's green: part of the ball.
    bool ballGreenAt(cv::Point p) const { return roles.field(classAt(p)) && !carpetAt(p); }
    // The pixel `r` px out from the centre in the unit direction (ca, sa).
    cv::Point along(double r, double ca, double sa) const
    {
        return {roundHalfAway(x + r * ca), roundHalfAway(y + r * sa)};
    }
};

// Thesis' first two tests: the non-green and non-black shares of the processed pixels in the
// candidate's square (and the share of the hinted ball colour). Green pixels count as green only
// when they are carpet (of the carpet's colour); in a square whose own non-green share reaches
// greenPanelMinOwnPct, also not an enclosed green panel, nor darker than the carpet around.
void scoreSquare(const Circle& c, int squareSide, ValidationScores& s)
{
    const int half = squareSide / 2;
    const int y0 = std::max(0, c.y - half), y1 = std::min(c.classes.rows - 1, c.y + half);
    const int x0 = std::max(0, c.x - half), x1 = std::min(c.classes.cols - 1, c.x + half);
    int used = 0;
    int colourGreen = 0;  // carpet by colour alone
    int black = 0;
    int hint = 0;
    for (int yy = y0; yy <= y1; ++yy) {
        const std::uint8_t* cls = c.classes.ptr<std::uint8_t>(yy);
        const std::uint8_t* u = c.geometry.usedMask().ptr<std::uint8_t>(yy);
        for (int xx = x0; xx <= x1; ++xx) {
            if (!u[xx]) continue;
            ++used;
            colourGreen += c.carpetColourAt({xx, yy});
            black += c.blackAt({xx, yy});
            hint += c.hint != ColorClass::Unknown && cls[xx] == std::uint8_t(c.hint);
        }
    }
    if (used > 0) {
        const double ownPct = 100.0 * (used - colourGreen) / used;
        // A square with enough of its own colour (a ball's white panels; carpet by a line corner
        // has little) is looked at again: its enclosed green panels (the walk) count as ball, and
        // (squareShadeTolerance) its green darker than the carpet around, when enough of the
        // square is neither carpet nor black (a robot's edge beside shaded carpet is not a ball).
        // Only then: the walk is costly, and a shadow on the carpet is all green.
        const bool shaded = c.options.squareShadeTolerance > 0.0 && c.byColour() &&
                            100.0 * (used - colourGreen - black) / used >= c.options.greenPanelMinOwnPct;
        int green = colourGreen;
        if (ownPct >= c.options.greenPanelMinOwnPct && (c.panels || shaded)) {
            green = 0;
            for (int yy = y0; yy <= y1; ++yy) {
                const std::uint8_t* u = c.geometry.usedMask().ptr<std::uint8_t>(yy);
                for (int xx = x0; xx <= x1; ++xx)
                    green += u[xx] && c.carpetColourAt({xx, yy}) && !(shaded && c.shadedAt({xx, yy})) &&
                             !(c.panels && c.panels->at({xx, yy}));
            }
        }
        s.nonGreenPct = ownPct < c.options.greenPanelMinOwnPct ? ownPct : 100.0 * (used - green) / used;
        s.nonBlackPct = 100.0 * (used - black) / used;
        s.hintPct = 100.0 * hint / used;
    }
}

// What one ray of the circularity test found.
struct BorderRay {
    bool judged = false;     // it says something of the shape (else it is left out)
    bool hit = false;        // the ball's border lies in the search band
    bool occluded = false;   // the border leads into a robot: the ray is not judged
    bool intoRobot = false;  // occluded by a robot's own colours (black, a marker), not a line or a foot
    double hitRadius = 0.0;  // px from the centre, when hit
    cv::Point2d hitAt;       // the border point relative to the centre, when hit
};

// A ray outwards that found no border and runs out over the hall floor (core/HallRay.h), judged
// by colour: a far ball at the carpet's edge has no border into carpet on its outer side.
void judgeHallRay(const Circle& c, double ca, double sa, double rMin, double rMax, BorderRay& ray)
{
    const ValidationOptions& options = c.options;
    if (!options.hallRaysByColour || !c.colour) return;
    const GeometryOptions& g = c.geometry.options();
    const cv::Point2d out(c.x - g.centerX, c.y - g.centerY);
    const double outLength = std::hypot(out.x, out.y);
    if (!(outLength > 0.0) || (ca * out.x + sa * out.y) / outLength < options.hallOutwardCos) return;
    // Cheap first: a ray whose reach ends short of the rim is no hall ray.
    const double reach = options.hallReachRadii * c.radius;
    if (outLength + rMax + reach < g.outerRadius) return;
    struct CircleHallPixels : HallPixels {
        explicit CircleHallPixels(const Circle& circle) : c(circle) {}
        bool known(cv::Point p) const override { return c.known(p); }
        bool carpet(cv::Point p) const override { return c.carpetAt(p); }
        // Outside the image (the frame ends what the mirror shows), or outside the ring; an
        // unprocessed pixel inside it is masked.
        bool pastRim(cv::Point p) const override
        {
            return p.x < 0 || p.y < 0 || p.x >= c.classes.cols || p.y >= c.classes.rows ||
                   c.geometry.distanceAt(p.x, p.y) > c.geometry.options().outerRadius;
        }
        std::array<std::uint8_t, 3> bgr(cv::Point p) const override { return c.colour->bgrAt(p.x, p.y); }
        const Circle& c;
    };
    // With circleFit a border anywhere up to rMax is a point for the fit, as traceBorder's.
    const double fromPx = options.circleFit ? 0.0 : rMin;
    const HallRay hall =
        hallRay({cv::Point2d(c.x, c.y), ca, sa, rMax}, fromPx, reach, options.hallColourStep, CircleHallPixels(c));
    if (!hall.border) return;  // over the floor without one: judged (as it was), and not round there
    ray.hit = true;
    ray.hitAt = cv::Point2d(hall.borderPx * ca, hall.borderPx * sa);
    ray.hitRadius = hall.borderPx;
}

// Walks one ray out from the centre (from the band's inner side when any edge in the band
// counts) and looks for the ball's border between rMin and rMax. With circleFit the border is
// the first edge into carpet anywhere up to rMax (edges into the ball's own colours are its
// inside); rMin is then only the fit's business.
BorderRay traceBorder(const Circle& c, double ca, double sa, double rMin, double rMax)
{
    const ValidationOptions& options = c.options;
    BorderRay ray;
    bool anyUsed = false;     // it crossed a processed pixel
    bool sawUnknown = false;  // it crossed a masked or out-of-mirror pixel
    bool prevBallGreen = false;
    auto edgeAt = [&](cv::Point p) { return c.known(p) && c.edgeAt(p); };
    cv::Point last(INT_MIN, INT_MIN);
    const double rStart = options.firstEdgeOnly || options.circleFit ? 0.5 : rMin;
    bool blocked = false;  // an edge inside the band came first
    LineContactRay line(c.classes, c.geometry, c.roles, c.x, c.y, ca, sa, options.lineContactMinEntry * c.radius,
                        options.lineContactReach * c.radius);
    ForeignContactRay object(c.classes, c.geometry, c.roles, c.ballClass, c.x, c.y, ca, sa,
                             options.lineContactMinEntry * c.radius, options.lineContactReach * c.radius);
    for (double r = rStart; r <= rMax + 1e-9 && !ray.hit && !blocked; r += 0.5) {
        const cv::Point p = c.along(r, ca, sa);
        if (p == last) continue;
        // A diagonal step could slip between the pixels of an 8-connected edge: look at the
        // two pixels it cuts across too, so that the ray is 4-connected.
        bool edge = false;
        cv::Point edgePixel = p;
        if (last.x != INT_MIN && p.x != last.x && p.y != last.y) {
            if (edgeAt({p.x, last.y}))
                edge = true, edgePixel = {p.x, last.y};
            else if (edgeAt({last.x, p.y}))
                edge = true, edgePixel = {last.x, p.y};
        }
        last = p;
        if (!c.known(p)) {
            sawUnknown = true;
            prevBallGreen = false;
            if (!edge) continue;
        } else {
            anyUsed = true;
            if (options.lineRaysUnknown && line.entersLine(p, r)) {
                ray.occluded = true;  // left out, like a ray into a robot
                return ray;
            }
            if (object.entersObject(p, r)) {
                ray.occluded = true;  // into feet or a robot's grey parts: as a line
                return ray;
            }
            if (c.edgeAt(p)) edge = true, edgePixel = p;
            // The ball's green meeting the carpet's green: the binary image has no edge there.
            const bool ballGreen = c.byColour() && c.ballGreenAt(p);
            if (!edge && prevBallGreen && c.carpetAt(p)) edge = true;
            prevBallGreen = ballGreen;
        }
        if (!edge) continue;
        // What lies just beyond the edge: carpet for a ball's border, a robot (black) when the
        // ball is partly hidden behind one: such a ray says nothing of the shape.
        const cv::Point b = c.along(r + options.beyondEdgePx, ca, sa);
        const bool beyondKnown = c.known(b);
        const std::uint8_t beyond = beyondKnown ? c.classAt(b) : std::uint8_t(ColorClass::Unknown);
        if (options.ignoreOccludedRays && c.robotAt(beyond)) {
            ray.occluded = ray.intoRobot = true;
            return ray;
        }
        const bool intoCarpet = !beyondKnown || c.carpetAt(b) || (c.roles.field(beyond) && c.carpetFollows(r, ca, sa));
        if (options.circleFit) {
            ray.hit = !options.borderIntoCarpet || intoCarpet;  // else an edge inside the ball
        } else if (r < rMin - 1e-9) {
            blocked = true;
        } else if (options.borderIntoCarpet) {
            ray.hit = intoCarpet;
            blocked = !ray.hit;
        } else {
            ray.hit = true;
        }
        if (ray.hit) {
            // The edge pixel's own offset: the ray's step lands up to ~0.7 px off it, a large
            // error on a ball of 3-6 px.
            ray.hitAt = options.borderAtPixel ? cv::Point2d(edgePixel.x - c.x, edgePixel.y - c.y) : cv::Point2d(r * ca, r * sa);
            ray.hitRadius = options.borderAtPixel ? std::hypot(ray.hitAt.x, ray.hitAt.y) : r;
        }
    }
    if (!ray.hit && !blocked && options.ignoreOccludedRays) {
        // No border at all: the ball may run on into a robot standing against it.
        const cv::Point e = c.along(rMax, ca, sa);
        ray.occluded = ray.intoRobot = c.known(e) && c.robotAt(c.classAt(e));
    }
    // A ray that found no border after passing unknown pixels may have lost it behind the mask.
    ray.judged = anyUsed && (ray.hit || blocked || !(sawUnknown && options.maskedRaysUnknown));
    if (ray.judged && !ray.hit && !blocked && !ray.occluded)
        judgeHallRay(c, ca, sa, rMin, rMax, ray);
    return ray;
}

// The circle through `points` (x, y relative to the candidate) by algebraic least squares
// (Kasa): x^2 + y^2 + D x + E y + F = 0, its 3x3 normal equations solved by Cramer's rule (no
// allocation: validation runs on every frame). False when the points do not determine one.
bool fitCircle(const std::vector<cv::Point2d>& points, cv::Point2d& centre, double& radius)
{
    if (points.size() < 5) return false;
    double a[3][3] = {};
    double b[3] = {};
    for (const auto& p : points) {
        const double row[3] = {p.x, p.y, 1.0};
        const double rhs = -(p.x * p.x + p.y * p.y);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) a[i][j] += row[i] * row[j];
            b[i] += row[i] * rhs;
        }
    }
    auto det = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    if (!(std::abs(d) > 1e-9)) return false;
    double sol[3];
    for (int k = 0; k < 3; ++k) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : a[i][j];
        sol[k] = det(m) / d;
    }
    centre = {-sol[0] / 2.0, -sol[1] / 2.0};
    const double r2 = centre.x * centre.x + centre.y * centre.y - sol[2];
    if (!(r2 > 0.0) || !std::isfinite(r2)) return false;
    radius = std::sqrt(r2);
    return true;
}

// The points within `tol` of the circle, into `in` (reused).
void nearCircle(const std::vector<cv::Point2d>& points, cv::Point2d centre, double radius, double tol,
                std::vector<cv::Point2d>& in)
{
    in.clear();
    for (const auto& p : points)
        if (std::abs(std::hypot(p.x - centre.x, p.y - centre.y) - radius) <= tol) in.push_back(p);
}

// The largest gap between the border of the circle (centre, radius), relative to the candidate,
// and the expected circle of radius `expected` around the candidate, along the unit directions
// `seen` (validation.fit_visible_border). Infinite when a direction misses the fitted circle.
double visibleBorderGap(cv::Point2d centre, double radius, double expected, const std::vector<cv::Point2d>& seen)
{
    double gap = 0.0;
    const double c2 = centre.x * centre.x + centre.y * centre.y;
    for (const cv::Point2d& u : seen) {
        const double cu = centre.x * u.x + centre.y * u.y;
        const double disc = radius * radius - c2 + cu * cu;
        if (disc < 0.0) return std::numeric_limits<double>::infinity();
        const double along = cu + std::sqrt(disc);  // where the ray from the candidate leaves the fitted circle
        gap = std::max(gap, std::abs(along - expected));
    }
    return gap;
}

// Thesis' third test: the share of the usable rays that find the ball's border in the band
// around the expected radius (circleFit: around the fitted circle), and how much the border's
// radius spreads.
void scoreCircularity(const Circle& c, ValidationScores& s)
{
    const ValidationOptions& options = c.options;
    const double band = std::max(options.radiusTolerance * c.radius, options.minRadiusBandPx);
    const double rMin = std::max(0.5, c.radius - band);
    const double rMax = options.circleFit ? c.radius + fitAllowance(c.radius, options) + band : c.radius + band;
    const int rays = rayCount(c.radius);
    int usable = 0;
    int robotRays = 0;
    int hits = 0;
    double hitSum = 0;
    double hitSq = 0;
    // Reused between candidates and frames: a warm pipeline allocates nothing.
    thread_local std::vector<cv::Point2d> points;
    thread_local std::vector<cv::Point2d> in;
    thread_local std::vector<cv::Point2d> seen;  // unit directions of the usable rays (on the circle)
    points.clear();
    seen.clear();
    for (int i = 0; i < rays; ++i) {
        const double a = 2.0 * M_PI * i / rays;
        const double ca = std::cos(a);
        const double sa = std::sin(a);
        // The band follows the ellipse; hits go back onto the circle of the same area.
        const double scale = c.reachAlong(ca, sa);
        const BorderRay ray = traceBorder(c, ca, sa, std::max(0.5, rMin * scale), rMax * scale);
        if (ray.intoRobot) ++robotRays;
        if (ray.occluded || !ray.judged) continue;
        ++usable;
        if (options.fitVisibleBorder) {
            const cv::Point2d onCircle = c.unsquash({ca * c.radius * scale, sa * c.radius * scale});
            seen.push_back(onCircle / std::max(1e-9, std::hypot(onCircle.x, onCircle.y)));
        }
        if (!ray.hit) continue;
        ++hits;
        const cv::Point2d at = c.unsquash(ray.hitAt);
        const double hitRadius = scale == 1.0 ? ray.hitRadius : std::hypot(at.x, at.y);
        hitSum += hitRadius;
        hitSq += hitRadius * hitRadius;
        points.push_back(at);
    }
    if (hits > 0) s.borderSpreadPx = std::sqrt(std::max(0.0, hitSq / hits - (hitSum / hits) * (hitSum / hits)));
    if (usable == 0 || usable < options.minUsableRayShare * rays) return;
    // Masked rays (rods, our body) are not in this share, nor rays into a line or a foot.
    if (usable < options.minUnoccludedRayShare * (usable + robotRays)) return;
    if (!options.circleFit) {
        s.circularityPct = 100.0 * hits / usable;
        return;
    }
    // Start from the expected circle, so that strays (a line beyond the ball) do not pull the
    // first fit; then refit to the points near each fit.
    cv::Point2d centre(0, 0);
    double radius = c.radius;
    const double allowance = fitAllowance(c.radius, options);
    nearCircle(points, centre, radius, allowance, in);
    for (double tol : {2.0 * band, band}) {
        if (!fitCircle(in, centre, radius)) return;
        nearCircle(points, centre, radius, tol, in);
    }
    s.fitRadiusPx = radius;
    s.fitDx = centre.x;
    s.fitDy = centre.y;
    // An arc of less than fitVisibleMinShare of the rays (a line crossing a rod) fits too much.
    if (options.fitVisibleBorder && usable >= options.fitVisibleMinShare * rays) s.fitBorderGapPx = visibleBorderGap(centre, radius, c.radius, seen);
    s.circularityPct = 100.0 * double(in.size()) / usable;
}

// The colour's chroma, max - min of its channels (0..255): unlike saturation it stays steady in
// dim light, where a few grey levels of noise swing (max - min) / max widely.
int chroma(const std::array<std::uint8_t, 3>& bgr)
{
    return int(std::max({bgr[0], bgr[1], bgr[2]})) - int(std::min({bgr[0], bgr[1], bgr[2]}));
}

// The mean of the three channels: a white line in dim light is brighter than an orange ball by
// this, though not by its brightest channel.
int channelMean(const std::array<std::uint8_t, 3>& bgr)
{
    return (int(bgr[0]) + int(bgr[1]) + int(bgr[2])) / 3;
}

// An unclassified centre's colour, read once per candidate for every ray of the run-on test.
struct CentreColour {
    int hue;     // OpenCV's 0-179
    int chroma;  // max - min of B, G, R
    int mean;    // mean of B, G, R
    std::array<std::uint8_t, 3> bgr;  // the 3x3 mean colour itself, B, G, R
};

// Whether an unclassified pixel is line paint beside an unclassified coloured centre: greyer by
// more than run_on_chroma_step and no darker. Only that breaks a run: a leg's or a robot's own
// shading (darker, or as coloured) must not, or their dim parts would pass as balls.
bool lineBesideColour(const std::array<std::uint8_t, 3>& pixel, const CentreColour& centre, double step)
{
    return chroma(pixel) < centre.chroma - step && channelMean(pixel) >= centre.mean;
}

// Whether an unclassified pixel is of another hue than an unclassified coloured centre
// (run_on_hue_step): another object's colour, such as a robot's marker band beside the ball.
// Both need run_on_hue_min_chroma, or noise on a grey or dark pixel decides its hue.
bool otherHue(const std::array<std::uint8_t, 3>& pixel, const CentreColour& centre, const ValidationOptions& options)
{
    if (options.runOnHueStep <= 0.0 || chroma(pixel) < options.runOnHueMinChroma ||
        centre.chroma < options.runOnHueMinChroma)
        return false;
    const int apart = std::abs(bgrToHsv(pixel[0], pixel[1], pixel[2]).h - centre.hue);
    return std::min(apart, 180 - apart) >= options.runOnHueStep;
}

// Whether an unclassified pixel's colour lies more than run_on_colour_step (B + G + R absolute
// differences) from an unclassified centre's and is no darker: another object, such as the hall
// floor beyond the carpet a ball lies against. A darker one may be the candidate's own shading or
// what it stands on (a leg's shoe), and does not end the run.
bool otherColour(const std::array<std::uint8_t, 3>& pixel, const CentreColour& centre, double step)
{
    if (step <= 0.0 || channelMean(pixel) < centre.mean) return false;
    int apart = 0;
    for (std::size_t k = 0; k < 3; ++k) apart += std::abs(int(pixel[k]) - int(centre.bgr[k]));
    return apart > step;
}

// Whether the centre's colour class goes on without a break along one ray out to `reach` px;
// nothing when the ray meets black (a robot) or an unprocessed pixel: it is not judged. With
// `centre` (run_on_chroma_step, run_on_hue_step, run_on_colour_step), the run also stops at
// unclassified line paint, another hue or another, no darker colour: the class says nothing of an
// unclassified pixel's colour.
std::optional<bool> runsOnAlong(const Circle& c, double ca, double sa, double reach,
                                const std::optional<CentreColour>& centre)
{
    int first = -1;
    for (double r = 0.0; r <= reach + 1e-9; r += 0.5) {
        const cv::Point p = c.along(r, ca, sa);
        if (!c.known(p)) return std::nullopt;
        const std::uint8_t cls = c.classAt(p);
        if (c.roles.black(cls)) return std::nullopt;
        if (c.roles.field(cls)) return false;
        if (first < 0)
            first = int(cls);
        else if (int(cls) != first)
            return false;
        if (centre && cls == std::uint8_t(ColorClass::Unknown)) {
            const auto bgr = c.colour->bgrAt(p.x, p.y);
            if ((c.options.runOnChromaStep > 0.0 && lineBesideColour(bgr, *centre, c.options.runOnChromaStep)) ||
                otherHue(bgr, *centre, c.options) || otherColour(bgr, *centre, c.options.runOnColourStep))
                return false;
        }
    }
    return true;
}

// The mean colour of the 3x3 pixels at the centre, when the centre is unclassified and
// run_on_chroma_step, run_on_hue_step or run_on_colour_step is on.
std::optional<CentreColour> unclassifiedCentreColour(const Circle& c)
{
    const cv::Point centre(c.x, c.y);
    if (!c.colour || (c.options.runOnChromaStep <= 0.0 && c.options.runOnHueStep <= 0.0 && c.options.runOnColourStep <= 0.0) ||
        !c.known(centre) ||
        c.classAt(centre) != std::uint8_t(ColorClass::Unknown))
        return std::nullopt;
    int sum[3] = {0, 0, 0};
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const cv::Point p(c.x + dx, c.y + dy);
            if (!c.known(p)) continue;
            const auto bgr = c.colour->bgrAt(p.x, p.y);
            for (int k = 0; k < 3; ++k) sum[k] += bgr[std::size_t(k)];
            ++n;
        }
    const std::array<std::uint8_t, 3> bgr{std::uint8_t(sum[0] / n), std::uint8_t(sum[1] / n), std::uint8_t(sum[2] / n)};
    return CentreColour{bgrToHsv(bgr[0], bgr[1], bgr[2]).h, chroma(bgr), channelMean(bgr), bgr};
}

// Our run-on test: the share of judged rays along which the centre's colour runs on beyond the
// circle. A line corner or line end continues as line; a ball on carpet (or beside a line) has
// carpet just outside it, and a ball never continues in its own colour.
void scoreRunOn(const Circle& c, ValidationScores& s)
{
    const ValidationOptions& options = c.options;
    const int rays = rayCount(c.radius);
    // A ball the fit found larger than expected is not its own colour running on.
    const double reach = options.runOnReach * std::max(c.radius, s.fitRadiusPx);
    const std::optional<CentreColour> centre = unclassifiedCentreColour(c);
    int judged = 0;
    int runOn = 0;
    for (int i = 0; i < rays; ++i) {
        const double a = 2.0 * M_PI * i / rays;
        const double ca = std::cos(a);
        const double sa = std::sin(a);
        const std::optional<bool> runs = runsOnAlong(c, ca, sa, reach * c.reachAlong(ca, sa), centre);
        if (!runs) continue;
        ++judged;
        runOn += *runs;
    }
    if (judged > 0) s.runOnPct = 100.0 * runOn / judged;
}

// The square's colour tests (thesis' first two): the one failed, or None.
RejectReason failedColourTest(const ValidationScores& s, const ValidationOptions& options, bool hintKnown)
{
    // The known ball colour shows the candidate is neither carpet nor robot.
    const bool hinted = hintKnown && s.hintPct >= options.ballHintMinPct;
    if (!hinted && s.nonGreenPct < options.minNonGreenPct) return RejectReason::NonGreen;
    if (!hinted && s.nonBlackPct < options.minNonBlackPct) return RejectReason::NonBlack;
    return RejectReason::None;
}

// The first test a scored candidate fails, in the thesis' order and then ours.
RejectReason firstFailedTest(const BallCandidate& c, const ValidationOptions& options, bool hintKnown, double minRadiusPx)
{
    if (c.expectedRadiusPx < minRadiusPx) return RejectReason::TooSmall;
    const RejectReason colour = failedColourTest(c.scores, options, hintKnown);
    if (colour != RejectReason::None) return colour;
    if (c.scores.circularityPct < requiredCircularityPct(c, options)) return RejectReason::Circularity;
    if (options.circleFit) {
        const double allowance = fitAllowance(c.expectedRadiusPx, options);
        const bool offModel = std::abs(c.scores.fitRadiusPx - c.expectedRadiusPx) > allowance ||
                              std::hypot(c.scores.fitDx, c.scores.fitDy) > allowance;
        const bool seenBorderFits = options.fitVisibleBorder && c.scores.fitBorderGapPx >= 0.0 &&
                                    c.scores.fitBorderGapPx <= allowance;
        if (offModel && !seenBorderFits) return RejectReason::Circularity;
    }
    if (c.scores.runOnPct > options.maxRunOnPct) return RejectReason::RunsOn;
    return RejectReason::None;
}

// Pale line pixels for the line-arms test (line_arms_pale): brighter than the carpet around the
// candidate by pale_line_min_value_ratio, or at least pale_line_value_cap (bright light); of the
// carpet's class, by pale_line_carpet_value_ratio and off the carpet's colour. None without the
// frame's colours or a carpet seen.
PaleLine paleLineAround(const FrameColour* colour, const cv::Mat& classes, const Geometry& geometry,
                        const ColourRoles& roles, const BallCandidate& c, const ValidationOptions& options)
{
    if (!options.lineArmsPale || !colour) return {};
    const CarpetColour carpet = carpetRingAround(*colour, classes, geometry, roles, c.x, c.y, c.expectedRadiusPx, options);
    if (!carpet.valid()) return {};
    double minValue = options.paleLineMinValueRatio * carpet.value();
    if (options.paleLineValueCap > 0.0) minValue = std::min(minValue, options.paleLineValueCap);
    const double carpetClassMinValue =
        options.paleLineCarpetValueRatio > 0.0 ? options.paleLineCarpetValueRatio * carpet.value() : -1.0;
    return {colour, options.paleLineMaxSaturation, minValue, carpetClassMinValue, carpet, options.carpetTolerance};
}

}  // namespace

CarpetColour carpetRingAround(const FrameColour& colour, const cv::Mat& classes, const Geometry& geometry,
                              const ColourRoles& roles, int x, int y, double radius, const ValidationOptions& options)
{
    return CarpetColour::around(colour, classes, geometry, roles, x, y,
                                options.carpetRingInner * radius + options.carpetRingMarginPx,
                                options.carpetRingOuter * radius + 2.0 * options.carpetRingMarginPx);
}

double nonBlackPctAt(int x, int y, double radius, int squareSide, const cv::Mat& classes, const Geometry& geometry,
                     const ValidationOptions& options, const FrameColour* colour, const ColourRoles& roles)
{
    const cv::Mat noEdges;
    Circle circle{x, y, radius, classes, noEdges, geometry, options, colour, roles, ColorClass::Unknown, {}, nullptr};
    if (colour && options.blackByLocalCarpet)
        circle.carpet = carpetRingAround(*colour, classes, geometry, roles, x, y, radius, options);
    const int half = squareSide / 2;
    int used = 0;
    int black = 0;
    for (int yy = std::max(0, y - half); yy <= std::min(classes.rows - 1, y + half); ++yy) {
        const std::uint8_t* u = geometry.usedMask().ptr<std::uint8_t>(yy);
        for (int xx = std::max(0, x - half); xx <= std::min(classes.cols - 1, x + half); ++xx) {
            if (!u[xx]) continue;
            ++used;
            black += circle.blackAt({xx, yy});
        }
    }
    return used > 0 ? 100.0 * (used - black) / used : 0.0;
}

ValidationScores scoreCircle(int x, int y, double radius, int squareSide, const cv::Mat& classes,
                             const cv::Mat& edges, const Geometry& geometry, const ValidationOptions& options,
                             const FrameColour* colour, const ColourRoles& roles, double squash, bool stopAtColour)
{
    Circle circle{x, y, radius, classes, edges, geometry, options, colour, roles, roles.idOf(options.ballHint), {}, nullptr};
    const cv::Point2d offset(x - geometry.options().centerX, y - geometry.options().centerY);
    const double offsetLength = std::hypot(offset.x, offset.y);
    if (options.radialSquash && radius >= options.squashMinRadiusPx && squash > 0.0 && offsetLength > 0.0) {
        circle.squash = squash;
        circle.radial = offset / offsetLength;
    }
    if (options.foreignRaysUnknown) circle.ballClass = ballClassAt(classes, roles, x, y);
    // Every test that reads colours (carpet ring, hall rays, run-on) reads them at class pixels.
    if (colour) CV_Assert(colour->frame().size() == classes.size());
    if (colour && (options.carpetByColour || options.blackByLocalCarpet))
        circle.carpet = carpetRingAround(*colour, classes, geometry, roles, x, y, radius, options);
    // The walk of the green-panel test reads classes only, never carpetAt (which asks it).
    struct CirclePanelPixels : PanelPixels {
        explicit CirclePanelPixels(const Circle& circle) : c(circle) {}
        bool known(cv::Point p) const override { return c.known(p); }
        bool field(cv::Point p) const override { return c.roles.field(c.classAt(p)); }
        const Circle& c;
    };
    const CirclePanelPixels pixels(circle);
    thread_local EnclosedPanels panels;  // its memo is reused between candidates
    if (options.greenPanels) {
        panels.reset(BallDisc{double(x), double(y), radius}, options.greenPanelMarginPx, options.greenPanelMinDirections, pixels);
        circle.panels = &panels;
    }
    ValidationScores s;
    scoreSquare(circle, squareSide, s);
    s.squareMeasured = true;
    const bool hintKnown = circle.hint != ColorClass::Unknown;  // as firstFailedTest's caller
    if (stopAtColour && failedColourTest(s, options, hintKnown) != RejectReason::None) return s;
    scoreCircularity(circle, s);
    scoreRunOn(circle, s);
    s.shapeMeasured = true;
    return s;
}

double fitAllowance(double expectedRadiusPx, const ValidationOptions& options)
{
    return std::max(options.fitMaxRadiusErrorPx, options.fitMaxRadiusError * expectedRadiusPx);
}

double requiredCircularityPct(const BallCandidate& c, const ValidationOptions& options)
{
    const bool fitsModel = !options.circleFit || std::abs(c.scores.fitRadiusPx - c.expectedRadiusPx) <=
                                                     options.clearMaxFitError * c.expectedRadiusPx;
    const bool clear = c.scores.nonBlackPct >= options.clearMinNonBlackPct &&
                       c.expectedRadiusPx >= options.clearMinRadiusPx && fitsModel;
    return clear ? std::min(options.minCircularityPct, options.minCircularityClearPct) : options.minCircularityPct;
}

bool rimCutBallPasses(const cv::Mat& classes, const Geometry& geometry, const ColourRoles& roles, int x, int y,
                      double distancePx, double expectedRadiusPx, double ballSquash, const ValidationOptions& options,
                      const FrameColour* colour)
{
    const double overhang = rimOverhangPx(distancePx, expectedRadiusPx, geometry.options().outerRadius, options.rimMarginPx);
    if (!options.refuseAtRim || overhang <= 0.0) return true;
    // Cut by the rim: judged only when its width and inward side show a ball on the carpet.
    if (!options.rimTest || overhang > options.rimMaxOverhangPx) return false;
    const double squash = options.radialSquash ? ballSquash : 1.0;
    const double width = rimExpectedWidthPx(expectedRadiusPx, squash);
    const double reach = options.rimMaxWidth * width;
    const double run =
        rimArcRunPx(classes, geometry, roles, x, y, reach, options.rimArcCarpetPx, options.rimArcMaskedMirrors);
    // The arcs beside the centre's are read only when it falls short of a ball's width.
    const double minRun = options.rimMinWidth * width;
    const bool wideEnough =
        run >= minRun || rimWidestArcRunPx(classes, geometry, roles, x, y, reach, options.rimArcCarpetPx,
                                           options.rimArcOffsetPx, options.rimArcMaskedMirrors) >= minRun;
    if (!wideEnough || run > reach) return false;
    if (rimClosure(classes, geometry, roles, x, y, expectedRadiusPx, squash, options.rimBandPx, options.rimInwardCos,
                   options.rimSkipInnerField)
            .closedPct() < options.rimMinClosedPct)
        return false;
    // And its colour is its own, not the floor's around it.
    if (!colour || options.rimMinContrast <= 0.0) return true;
    const std::optional<double> contrast =
        surroundContrast(*colour, classes, geometry.usedMask(), roles, x, y, expectedRadiusPx);
    return !contrast || *contrast >= options.rimMinContrast;
}

void validateCandidate(BallCandidate& c, const cv::Mat& classes, const cv::Mat& edges, const Geometry& geometry,
                       const BallModel& ball, const ValidationOptions& options, const FrameColour* colour,
                       const ColourRoles& roles, bool stopAtColour)
{
    CV_Assert(classes.type() == CV_8UC1 && edges.type() == CV_8UC1 && classes.size() == edges.size());
    if (stopAtColour && c.rejected != RejectReason::None) {
        c.scores = ValidationScores{};  // already out (outside the area, too large): nothing to explain
        return;
    }
    const int square = ball.squareSizeAt(c.distancePx, imageAngleAt(geometry, c.x, c.y));
    c.scores = scoreCircle(c.x, c.y, c.expectedRadiusPx, square, classes, edges, geometry, options, colour, roles,
                           ball.squashAt(c.distancePx), stopAtColour);
    if (c.rejected != RejectReason::None) return;  // already out (outside the area, too large)
    double minRadiusPx = options.minRadiusPx;
    const double overhang = rimOverhangPx(c.distancePx, c.expectedRadiusPx, geometry.options().outerRadius, options.rimMarginPx);
    if (options.refuseAtRim && overhang > 0.0) {
        if (!rimCutBallPasses(classes, geometry, roles, c.x, c.y, c.distancePx, c.expectedRadiusPx,
                              ball.squashAt(c.distancePx), options, colour)) {
            c.rejected = RejectReason::OutsideArea;
            return;
        }
        minRadiusPx = std::min(minRadiusPx, options.rimMinRadiusPx);
    }
    c.rejected = firstFailedTest(c, options, roles.idOf(options.ballHint) != ColorClass::Unknown, minRadiusPx);
    if (c.rejected != RejectReason::None || !options.lineArms) return;
    // Arms are looked for on far candidates only. Nearer ones (up to line_blob_cut_max_radius_px)
    // count as armless for the cut-blob test below, unless their cut disc reaches our body: a
    // ball touching it is cut by it all the time.
    const bool small = c.expectedRadiusPx <= options.lineArmsMaxRadiusPx;
    const bool clearOfBody =
        c.distancePx - options.lineBlobCutReach * c.expectedRadiusPx > geometry.options().innerRadius;
    if (small || (c.expectedRadiusPx <= options.lineBlobCutMaxRadiusPx && clearOfBody)) {
        const PaleLine pale = paleLineAround(colour, classes, geometry, roles, c, options);
        LineArms arms;
        if (small) {
            // From the ball's border as the fit found it: a larger ball's tangent line is no arm.
            const double radius = std::max(c.expectedRadiusPx, c.scores.fitRadiusPx);
            arms = lineArmsAround(classes, geometry, roles, c.x, c.y, radius, options.lineArmsReach,
                                  options.lineArmsLateralPx, pale);
        }
        if (arms.junction(options.lineArmsMaxAngleDeg)) {
            c.rejected = RejectReason::LineJunction;
            return;
        }
        const bool armed = arms.count >= 1;
        const double blobMinPct = armed ? options.lineBlobMinPct : options.lineBlobArmlessMinPct;
        if (blobMinPct >= 100.0) return;
        const DiscShares disc = discShares(classes, geometry, roles, c.x, c.y, options.lineBlobDisc * c.expectedRadiusPx, pale);
        if (disc.linePct < blobMinPct) return;
        if (armed) {
            c.rejected = RejectReason::LineJunction;
            return;
        }
        // Without an arm: a blob whose line runs on behind a rod, our body or the rim (its arm ended
        // there), unless it shows a ball's panels. One in the open (the penalty spot, a white ball)
        // passes.
        if (disc.panelPct > options.lineBlobArmlessMaxPanelPct) return;
        const bool cut = options.lineBlobCutReach <= 0.0 ||
                         discShares(classes, geometry, roles, c.x, c.y, options.lineBlobCutReach * c.expectedRadiusPx)
                                 .unusedPct > 0.0;
        if (cut) c.rejected = RejectReason::LineBlob;
    }
}

}  // namespace omnitune
