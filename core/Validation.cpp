#include "core/Validation.h"

#include "core/BallModel.h"
#include "core/ColorClass.h"
#include "core/Geometry.h"

#include <algorithm>
#include <climits>
#include <cmath>
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

    // Inside the image and processed: its class and edge say something about the scene.
    bool known(cv::Point p) const
    {
        return p.x >= 0 && p.y >= 0 && p.x < classes.cols && p.y < classes.rows && geometry.isUsed(p.x, p.y);
    }
    ColorClass classAt(cv::Point p) const { return ColorClass(classes.ptr<std::uint8_t>(p.y)[p.x]); }
    bool edgeAt(cv::Point p) const { return edges.ptr<std::uint8_t>(p.y)[p.x] != 0; }
    // The pixel `r` px out from the centre in the unit direction (ca, sa).
    cv::Point along(double r, double ca, double sa) const
    {
        return {int(std::lround(x + r * ca)), int(std::lround(y + r * sa))};
    }
};

// Thesis' first two tests: the non-green and non-black shares of the processed pixels in the
// candidate's square.
void scoreSquare(const Circle& c, int squareSide, ValidationScores& s)
{
    const int half = squareSide / 2;
    int used = 0;
    int green = 0;
    int black = 0;
    for (int yy = std::max(0, c.y - half); yy <= std::min(c.classes.rows - 1, c.y + half); ++yy) {
        const std::uint8_t* cls = c.classes.ptr<std::uint8_t>(yy);
        const std::uint8_t* u = c.geometry.usedMask().ptr<std::uint8_t>(yy);
        for (int xx = std::max(0, c.x - half); xx <= std::min(c.classes.cols - 1, c.x + half); ++xx) {
            if (!u[xx]) continue;
            ++used;
            green += cls[xx] == std::uint8_t(ColorClass::Green);
            black += cls[xx] == std::uint8_t(ColorClass::Black);
        }
    }
    if (used > 0) {
        s.nonGreenPct = 100.0 * (used - green) / used;
        s.nonBlackPct = 100.0 * (used - black) / used;
    }
}

// What one ray of the circularity test found.
struct BorderRay {
    bool anyUsed = false;    // it crossed a processed pixel (else it says nothing of the shape)
    bool hit = false;        // the ball's border lies in the search band
    bool occluded = false;   // the border leads into a robot: the ray is not judged
    double hitRadius = 0.0;  // px from the centre, when hit
};

// Walks one ray out from the centre (from the band's inner side when any edge in the band
// counts) and looks for the ball's border between rMin and rMax.
BorderRay traceBorder(const Circle& c, double ca, double sa, double rMin, double rMax, const ValidationOptions& options)
{
    BorderRay ray;
    auto edgeAt = [&](cv::Point p) {
        if (!c.known(p)) return false;
        ray.anyUsed = true;
        return c.edgeAt(p);
    };
    cv::Point last(INT_MIN, INT_MIN);
    const double rStart = options.firstEdgeOnly ? 0.5 : rMin;
    bool blocked = false;  // an edge inside the band came first
    for (double r = rStart; r <= rMax + 1e-9 && !ray.hit && !blocked; r += 0.5) {
        const cv::Point p = c.along(r, ca, sa);
        if (p == last) continue;
        // A diagonal step could slip between the pixels of an 8-connected edge: look at the
        // two pixels it cuts across too, so that the ray is 4-connected.
        bool edge = false;
        if (last.x != INT_MIN && p.x != last.x && p.y != last.y)
            edge = edgeAt({p.x, last.y}) || edgeAt({last.x, p.y});
        edge = edgeAt(p) || edge;
        last = p;
        if (!edge) continue;
        // What lies just beyond the edge: carpet for a ball's border, a robot (black) when the
        // ball is partly hidden behind one: such a ray says nothing of the shape.
        const cv::Point b = c.along(r + options.beyondEdgePx, ca, sa);
        const bool beyondKnown = c.known(b);
        const ColorClass beyond = beyondKnown ? c.classAt(b) : ColorClass::Unknown;
        if (options.ignoreOccludedRays && beyond == ColorClass::Black) {
            ray.occluded = true;
            return ray;
        }
        if (r < rMin - 1e-9) {
            blocked = true;
        } else if (options.borderIntoCarpet) {
            ray.hit = !beyondKnown || beyond == ColorClass::Green;
            blocked = !ray.hit;
        } else {
            ray.hit = true;
        }
        if (ray.hit) ray.hitRadius = r;
    }
    if (!ray.hit && !blocked && options.ignoreOccludedRays) {
        // No border at all: the ball may run on into a robot standing against it.
        const cv::Point e = c.along(rMax, ca, sa);
        ray.occluded = c.known(e) && c.classAt(e) == ColorClass::Black;
    }
    return ray;
}

// Thesis' third test: the share of the usable rays that find the ball's border in the band
// around the expected radius, and how much the border's radius spreads.
void scoreCircularity(const Circle& c, const ValidationOptions& options, ValidationScores& s)
{
    const double band = std::max(options.radiusTolerance * c.radius, options.minRadiusBandPx);
    const double rMin = std::max(0.5, c.radius - band);
    const double rMax = c.radius + band;
    const int rays = rayCount(c.radius);
    int usable = 0;
    int hits = 0;
    double hitSum = 0;
    double hitSq = 0;
    for (int i = 0; i < rays; ++i) {
        const double a = 2.0 * M_PI * i / rays;
        const BorderRay ray = traceBorder(c, std::cos(a), std::sin(a), rMin, rMax, options);
        if (ray.occluded) continue;
        usable += ray.anyUsed;
        if (!ray.hit) continue;
        ++hits;
        hitSum += ray.hitRadius;
        hitSq += ray.hitRadius * ray.hitRadius;
    }
    if (usable > 0 && usable >= options.minUsableRayShare * rays) s.circularityPct = 100.0 * hits / usable;
    if (hits > 0) s.borderSpreadPx = std::sqrt(std::max(0.0, hitSq / hits - (hitSum / hits) * (hitSum / hits)));
}

// Whether the centre's colour class goes on without a break along one ray out to `reach` px;
// nothing when the ray meets black (a robot) or an unprocessed pixel: it is not judged.
std::optional<bool> runsOnAlong(const Circle& c, double ca, double sa, double reach)
{
    int first = -1;
    for (double r = 0.0; r <= reach + 1e-9; r += 0.5) {
        const cv::Point p = c.along(r, ca, sa);
        if (!c.known(p)) return std::nullopt;
        const ColorClass cls = c.classAt(p);
        if (cls == ColorClass::Black) return std::nullopt;
        if (cls == ColorClass::Green) return false;
        if (first < 0)
            first = int(cls);
        else if (int(cls) != first)
            return false;
    }
    return true;
}

// Our run-on test: the share of judged rays along which the centre's colour runs on beyond the
// circle. A line corner or line end continues as line; a ball on carpet (or beside a line) has
// carpet just outside it, and a ball never continues in its own colour.
void scoreRunOn(const Circle& c, const ValidationOptions& options, ValidationScores& s)
{
    const int rays = rayCount(c.radius);
    const double reach = options.runOnReach * c.radius;
    int judged = 0;
    int runOn = 0;
    for (int i = 0; i < rays; ++i) {
        const double a = 2.0 * M_PI * i / rays;
        const std::optional<bool> runs = runsOnAlong(c, std::cos(a), std::sin(a), reach);
        if (!runs) continue;
        ++judged;
        runOn += *runs;
    }
    if (judged > 0) s.runOnPct = 100.0 * runOn / judged;
}

// The first test a scored candidate fails, in the thesis' order and then ours.
RejectReason firstFailedTest(const BallCandidate& c, const ValidationOptions& options)
{
    if (c.expectedRadiusPx < options.minRadiusPx) return RejectReason::TooSmall;
    if (c.scores.nonGreenPct < options.minNonGreenPct) return RejectReason::NonGreen;
    if (c.scores.nonBlackPct < options.minNonBlackPct) return RejectReason::NonBlack;
    if (c.scores.circularityPct < options.minCircularityPct) return RejectReason::Circularity;
    if (c.scores.runOnPct > options.maxRunOnPct) return RejectReason::RunsOn;
    return RejectReason::None;
}

}  // namespace

ValidationScores scoreCircle(int x, int y, double radius, int squareSide, const cv::Mat& classes,
                             const cv::Mat& edges, const Geometry& geometry, const ValidationOptions& options)
{
    const Circle circle{x, y, radius, classes, edges, geometry};
    ValidationScores s;
    scoreSquare(circle, squareSide, s);
    scoreCircularity(circle, options, s);
    scoreRunOn(circle, options, s);
    return s;
}

void validateCandidate(BallCandidate& c, const cv::Mat& classes, const cv::Mat& edges, const Geometry& geometry,
                       const BallModel& ball, const ValidationOptions& options)
{
    CV_Assert(classes.type() == CV_8UC1 && edges.type() == CV_8UC1 && classes.size() == edges.size());
    c.scores = scoreCircle(c.x, c.y, c.expectedRadiusPx, ball.squareSizeAt(c.distancePx), classes, edges,
                           geometry, options);
    if (c.rejected != RejectReason::None) return;  // already out (outside the area, too large)
    c.rejected = firstFailedTest(c, options);
}

}  // namespace omnitune
