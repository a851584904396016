#include "core/Validation.h"

#include "core/BallModel.h"
#include "core/ColorClass.h"
#include "core/Geometry.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace omnitune {

namespace {

// Circle search rays: about one per pixel of circumference, never fewer than 16.
int rayCount(double radius) { return std::max(16, int(std::ceil(2.0 * M_PI * radius))); }

// Rays whose whole search band lies on unprocessed pixels (robot body, rods) say nothing about
// the shape; they are left out. Under this share of usable rays the circle is not judged.
constexpr double kMinUsableRayShare = 0.25;

// How far out, in expected radii, the centre's colour must run on for a ray to count in the
// run-on test: past the ball's blurred border (~1 px) but not as far as a nearby line (balls
// beside a line keep a strip of carpet). 1.5 and 1.75 left far line corners at 11 %, barely
// above a white ball touching a line (10 %); 1.3 puts them at 18.5 % and more.
constexpr double kRunOnReach = 1.3;

}  // namespace

ValidationScores scoreCircle(int x, int y, double radius, int squareSide, const cv::Mat& classes,
                             const cv::Mat& edges, const Geometry& geometry, const ValidationOptions& options)
{
    ValidationScores s;
    const int w = classes.cols;
    const int h = classes.rows;
    const int half = squareSide / 2;
    int used = 0;
    int green = 0;
    int black = 0;
    for (int yy = std::max(0, y - half); yy <= std::min(h - 1, y + half); ++yy) {
        const std::uint8_t* c = classes.ptr<std::uint8_t>(yy);
        const std::uint8_t* u = geometry.usedMask().ptr<std::uint8_t>(yy);
        for (int xx = std::max(0, x - half); xx <= std::min(w - 1, x + half); ++xx) {
            if (!u[xx]) continue;
            ++used;
            green += c[xx] == std::uint8_t(ColorClass::Green);
            black += c[xx] == std::uint8_t(ColorClass::Black);
        }
    }
    if (used > 0) {
        s.nonGreenPct = 100.0 * (used - green) / used;
        s.nonBlackPct = 100.0 * (used - black) / used;
    }

    const double band = std::max(options.radiusTolerance * radius, options.minRadiusBandPx);
    const double rMin = std::max(0.5, radius - band);
    const double rMax = radius + band;
    const int rays = rayCount(radius);
    int usable = 0;
    int hits = 0;
    double hitSum = 0;
    double hitSq = 0;
    auto edgeAt = [&](int px, int py, bool& anyUsed) {
        if (px < 0 || py < 0 || px >= w || py >= h || !geometry.isUsed(px, py)) return false;
        anyUsed = true;
        return edges.ptr<std::uint8_t>(py)[px] != 0;
    };
    for (int i = 0; i < rays; ++i) {
        const double a = 2.0 * M_PI * i / rays;
        const double ca = std::cos(a);
        const double sa = std::sin(a);
        bool anyUsed = false;
        bool hit = false;
        int lastX = INT_MIN;
        int lastY = INT_MIN;
        // From the centre when only the first edge counts, else from the band's inner side.
        const double rStart = options.firstEdgeOnly ? 0.5 : rMin;
        bool blocked = false;   // an edge inside the band came first
        bool occluded = false;  // the border leads into a robot: not judged
        for (double r = rStart; r <= rMax + 1e-9 && !hit && !blocked; r += 0.5) {
            const int px = int(std::lround(x + r * ca));
            const int py = int(std::lround(y + r * sa));
            if (px == lastX && py == lastY) continue;
            // A diagonal step could slip between the pixels of an 8-connected edge: look at
            // the two pixels it cuts across too, so that the ray is 4-connected.
            bool edge = false;
            if (lastX != INT_MIN && px != lastX && py != lastY)
                edge = edgeAt(px, lastY, anyUsed) || edgeAt(lastX, py, anyUsed);
            edge = edgeAt(px, py, anyUsed) || edge;
            lastX = px;
            lastY = py;
            if (!edge) continue;
            // What lies 1.5 px beyond the edge: carpet for a ball's border, a robot (black)
            // when the ball is partly hidden behind one: such a ray says nothing of the shape.
            const int bx = int(std::lround(x + (r + 1.5) * ca));
            const int by = int(std::lround(y + (r + 1.5) * sa));
            const bool beyondKnown = bx >= 0 && by >= 0 && bx < w && by < h && geometry.isUsed(bx, by);
            const auto beyond = beyondKnown ? ColorClass(classes.ptr<std::uint8_t>(by)[bx]) : ColorClass::Unknown;
            if (options.ignoreOccludedRays && beyond == ColorClass::Black) {
                occluded = true;
                break;
            }
            if (r < rMin - 1e-9)
                blocked = true;
            else if (options.borderIntoCarpet) {
                hit = !beyondKnown || beyond == ColorClass::Green;
                blocked = !hit;
            } else {
                hit = true;
            }
            if (hit) {
                hitSum += r;
                hitSq += r * r;
            }
        }
        if (!hit && !blocked && !occluded && options.ignoreOccludedRays) {
            // No border at all: the ball may run on into a robot standing against it.
            const int ex = int(std::lround(x + rMax * ca));
            const int ey = int(std::lround(y + rMax * sa));
            occluded = ex >= 0 && ey >= 0 && ex < w && ey < h && geometry.isUsed(ex, ey) &&
                       classes.ptr<std::uint8_t>(ey)[ex] == std::uint8_t(ColorClass::Black);
        }
        if (occluded) continue;
        usable += anyUsed;
        hits += hit;
    }
    if (usable >= kMinUsableRayShare * rays) s.circularityPct = 100.0 * hits / usable;
    if (hits > 0) s.borderSpreadPx = std::sqrt(std::max(0.0, hitSq / hits - (hitSum / hits) * (hitSum / hits)));

    // Run-on test: rays along which the centre's colour class goes on without a break from the
    // centre out beyond the circle. A line corner or line end continues as line; a ball on
    // carpet (or beside a line) has carpet just outside it, and a ball never continues in its
    // own colour. Rays meeting black (a robot) or unprocessed pixels are not judged.
    const double runTo = kRunOnReach * radius;
    int judged = 0;
    int runOn = 0;
    for (int i = 0; i < rays; ++i) {
        const double a = 2.0 * M_PI * i / rays;
        const double ca = std::cos(a);
        const double sa = std::sin(a);
        bool known = true;
        bool runs = true;
        int first = -1;
        for (double r = 0.0; r <= runTo + 1e-9 && known && runs; r += 0.5) {
            const int px = int(std::lround(x + r * ca));
            const int py = int(std::lround(y + r * sa));
            if (px < 0 || py < 0 || px >= w || py >= h || !geometry.isUsed(px, py)) {
                known = false;
                break;
            }
            const int cls = classes.ptr<std::uint8_t>(py)[px];
            if (cls == int(ColorClass::Black))
                known = false;
            else if (cls == int(ColorClass::Green))
                runs = false;
            else if (first < 0)
                first = cls;
            else if (cls != first)
                runs = false;
        }
        if (!known) continue;
        ++judged;
        runOn += runs;
    }
    if (judged > 0) s.runOnPct = 100.0 * runOn / judged;
    return s;
}

void validateCandidate(BallCandidate& c, const cv::Mat& classes, const cv::Mat& edges, const Geometry& geometry,
                       const BallModel& ball, const ValidationOptions& options)
{
    CV_Assert(classes.type() == CV_8UC1 && edges.type() == CV_8UC1 && classes.size() == edges.size());
    c.scores = scoreCircle(c.x, c.y, c.expectedRadiusPx, ball.squareSizeAt(c.distancePx), classes, edges,
                           geometry, options);
    if (c.rejected != RejectReason::None) return;  // already out (outside the area, too large)
    if (c.expectedRadiusPx < options.minRadiusPx)
        c.rejected = RejectReason::TooSmall;
    else if (c.scores.nonGreenPct < options.minNonGreenPct)
        c.rejected = RejectReason::NonGreen;
    else if (c.scores.nonBlackPct < options.minNonBlackPct)
        c.rejected = RejectReason::NonBlack;
    else if (c.scores.circularityPct < options.minCircularityPct)
        c.rejected = RejectReason::Circularity;
    else if (c.scores.runOnPct > options.maxRunOnPct)
        c.rejected = RejectReason::RunsOn;
}

}  // namespace omnitune
