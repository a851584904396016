#pragma once
// Issue 11's remounted camera, shared by the remount tests (calib/remount_*, app/setup_*): the
// optics simulator's hyperbolic 640x480 camera on three support rods, and the same camera after
// a remount (principal point moved, mirror 1 cm higher on its rods, rods turned 20 degrees).
// Header-only test support: the tours are rendered frame by frame with the optics' own truth.
#include "calib/eval/Evaluation.h"
#include "calib/session/TruthCsv.h"
#include "calib/sim/optics/OpticsCell.h"
#include "calib/sim/optics/OpticsRenderer.h"
#include "core/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace omnitune::remount {

constexpr int kTourFrames = 40;

inline OpticsCell tourCell()
{
    OpticsCell cell;
    cell.frames = kTourFrames;
    return cell;
}

// The camera before the remount: the cell's camera with three support rods (the tour's balls
// are clear of them).
inline CatadioptricCameraParams originalMount(const OpticsCell& cell)
{
    CatadioptricCameraParams mount = opticsCellCameraParams(cell);
    mount.rods = hyperbolicCameraParams(cell.image, 3).rods;
    return mount;
}

// The same camera after a remount: the camera shifted under the mirror, the mirror 1 cm
// higher on its rods, the rods turned 20 degrees about the robot's axis.
inline CatadioptricCameraParams remounted(CatadioptricCameraParams p)
{
    p.principal += cv::Point2d(7.0, -5.0);
    const double rise = 0.01;
    p.vertexAboveCamera += rise;
    p.measuredViewpointHeight += rise;
    const double a = 20.0 * CV_PI / 180.0, c = std::cos(a), s = std::sin(a);
    for (SupportRod& rod : p.rods) {
        for (cv::Point3d* end : {&rod.bottom, &rod.top})
            *end = cv::Point3d(c * end->x - s * end->y, s * end->x + c * end->y, end->z);
        rod.top.z += rise;
    }
    p.name += "-remounted";
    return p;
}

// Where the robot's axis is seen: the centre of the images of floor circles 3 m around the
// robot (the point the distance map measures from; the mirror rim's mean may lie a little off).
inline cv::Point2d fieldCentre(const CatadioptricCamera& camera)
{
    cv::Point2d sum;
    int n = 0;
    for (int k = 0; k < 36; ++k) {
        const double a = 2 * CV_PI * k / 36;
        if (const auto p = camera.project({3.0 * std::cos(a), 3.0 * std::sin(a), 0.0})) {
            sum += *p;
            ++n;
        }
    }
    return n ? sum / n : cv::Point2d(-1, -1);
}

struct Tour {
    std::vector<cv::Mat> frames;
    std::map<int, TruthRow> truth;
    std::vector<OpticsTruth> optics;  // per frame: visible share, ground distance, ...
};

inline Tour renderTour(const OpticsCell& cell, const OpticsRenderer& renderer)
{
    Tour t;
    for (int i = 0; i < cell.frames; ++i) {
        OpticsTruth truth;
        t.frames.push_back(renderer.render(opticsCellScene(cell, i, renderer), &truth));
        t.truth[i] = toTruthRow(truth, i, cell.ballPresent);
        t.optics.push_back(truth);
    }
    return t;
}

// The farthest ground distance (m) of a visible ball whose circle lies inside `g`'s ring: the
// detector does not look past outer_radius, so that is how far the camera can find a ball.
inline double ringReachM(const Tour& tour, const GeometryOptions& g)
{
    double reach = 0;
    for (std::size_t i = 0; i < tour.optics.size(); ++i) {
        const TruthRow& t = tour.truth.at(int(i));
        if (t.ballVisible && std::hypot(t.px - g.centerX, t.py - g.centerY) + t.radiusPx <= g.outerRadius)
            reach = std::max(reach, tour.optics[i].distanceM);
    }
    return reach;
}

// `tour` with truth only for the frames whose ball lies within `maxM` m: the other frames are
// not annotated, so evaluate() leaves them out.
inline Tour within(const Tour& tour, double maxM)
{
    Tour t = tour;
    for (std::size_t i = 0; i < tour.optics.size(); ++i)
        if (tour.optics[i].distanceM > maxM) t.truth.erase(int(i));
    return t;
}

inline EvaluationRow evaluateTour(const Tour& tour, const Config& config)
{
    Pipeline pipeline(config);
    std::vector<FrameOutcome> outcomes;
    PipelineResult result;
    for (int i = 0; i < int(tour.frames.size()); ++i) {
        pipeline.process(tour.frames[i], PixelFormat::Bgr8, result);
        outcomes.push_back(outcomeOf(i, result));
    }
    return evaluate(outcomes, tour.truth);
}

}  // namespace omnitune::remount
