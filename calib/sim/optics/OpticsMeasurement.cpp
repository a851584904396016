#include "calib/sim/optics/OpticsMeasurement.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <vector>

namespace omnitune {

namespace {

bool seesWorld(const CatadioptricCamera& camera, const cv::Point2d& p)
{
    const int x = int(std::lround(p.x)), y = int(std::lround(p.y));
    const cv::Size s = camera.imageSize();
    if (x < 2 || y < 2 || x >= s.width - 2 || y >= s.height - 2) return false;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
            if (camera.kind(x + dx, y + dy) != CatadioptricCamera::PixelKind::World) return false;
    return true;
}

}  // namespace

CameraMeasurements measureOpticsCamera(const OpticsRenderer& renderer, const OpticsMeasurementOptions& options)
{
    const CatadioptricCamera& camera = renderer.camera();
    CameraMeasurements m;
    cv::RNG rng(options.seed);
    m.viewpointHeight = camera.params().measuredViewpointHeight;

    // Floor marks: every nearMarkStepM against the body, then every markStepM along each
    // direction as far as the mirror shows them.
    std::vector<double> marks;
    const double nearTo = options.firstMarkM + options.markStepM - 1e-9;  // the second far mark, exclusive
    for (int i = 0; options.nearMarksFromM + i * options.nearMarkStepM < nearTo; ++i)
        marks.push_back(options.nearMarksFromM + i * options.nearMarkStepM);
    for (double d = options.firstMarkM + options.markStepM; d < 12.0; d += options.markStepM) marks.push_back(d);
    for (int k = 0; k < options.markDirections; ++k) {
        const double a = 2 * CV_PI * (k + 0.25) / options.markDirections;
        for (double d : marks) {
            const auto p = camera.project({d * std::cos(a), d * std::sin(a), 0.0});
            if (!p) {
                if (d > options.firstMarkM) break;  // past the rim
                continue;
            }
            if (!seesWorld(camera, *p)) continue;  // behind a rod or the body, or out of the frame
            CalibrationPoint c;
            c.fromImagePoint = true;
            c.xPx = p->x + rng.gaussian(options.locateNoisePx);
            c.yPx = p->y + rng.gaussian(options.locateNoisePx);
            c.distanceM = d;
            m.points.push_back(c);
        }
    }

    // The ball at known distances around the robot; its circle is the silhouette's.
    OpticsScene scene;
    scene.robot = {-4.0, 0.0, 0.0};
    for (int k = 0; k < options.ballDirections; ++k) {
        const double a = 2 * CV_PI * (k + 0.5) / options.ballDirections;
        for (double d : {0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0}) {
            scene.ball = toFieldFrame(scene.robot, {d * std::cos(a), d * std::sin(a)});
            const OpticsTruth t = renderer.ballTruth(scene);
            if (t.area <= 0 || t.visibleFraction < 0.97) continue;  // the team lays it where it is seen whole
            m.balls.push_back({t.px + rng.gaussian(options.locateNoisePx), t.py + rng.gaussian(options.locateNoisePx),
                               t.radiusPx + rng.gaussian(options.radiusNoisePx), d});
        }
    }

    // Empty field while the robot drives and turns.
    for (int i = 0; i < options.emptyFrames; ++i) {
        OpticsScene empty;
        empty.ballPresent = false;
        empty.robot = {-5.0 + 2.0 * i, (i % 2 ? 1.5 : -1.0), 0.7 * i};
        empty.seed = options.seed + unsigned(i);
        m.emptyFrames.push_back(renderer.render(empty));
    }

    // The mask: rods, the mast and the body painted out, 2 px wider.
    const cv::Size size = camera.imageSize();
    cv::Mat hidden(size, CV_8UC1, cv::Scalar(0));
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            const auto kind = camera.kind(x, y);
            if (kind == CatadioptricCamera::PixelKind::Rod || kind == CatadioptricCamera::PixelKind::Body ||
                kind == CatadioptricCamera::PixelKind::Mast)
                hidden.at<uchar>(y, x) = 255;
        }
    if (options.maskDilatePx > 0)
        cv::dilate(hidden, hidden, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * options.maskDilatePx + 1, 2 * options.maskDilatePx + 1}));
    m.mask = 255 - hidden;
    return m;
}

}  // namespace omnitune
