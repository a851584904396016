// Issue 10's "done when", on the optics simulator (calib/sim/optics; robots, feet and shadows
// about): starting from the default colours, on a dim tour and on a tour over a cyan-green
// carpet past the default green box (OpticsCarpet::Teal), the automatic first calibration
// (AutoColour, from three frames) and then at most three sampling strokes (ClassSampling, on the
// ball and carpet where the simulator's truth says they are) bring the detector to >= 95 % of the
// balls within reach, those touching a line included, never below the default colours, and make
// the ball's pixels the ball class; the automatic calibration alone reaches 95 % of the balls
// within reach of a dim and of a bright tour, those touching a line or feet included. Each run
// prints the detection with the default colours, after the automatic calibration and after the
// strokes (OMNITUNE_DEBUG_MISSES=1 lists every miss with its cause).
#include "calib/colour/AutoColour.h"
#include "calib/colour/ClassSampling.h"
#include "calib/colour/ColourSamples.h"
#include "calib/colour/SampleArea.h"
#include "calib/eval/Evaluation.h"
#include "calib/eval/FrameDiagnosis.h"
#include "calib/sim/optics/OpticsCell.h"
#include "core/ConfigSchema.h"
#include "core/Pipeline.h"

#include <opencv2/imgproc.hpp>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace omnitune;

namespace {

constexpr int kFrames = 36;          // ball positions spread 0.5..5 m around the robot
constexpr int kCalibrationFrames = 3;  // what a user shows the automatic calibration
constexpr double kDoneWhenPct = 95.0;
// Balls farther than this are at the edge of the detector's reach whatever the colours (at
// 640x480 they are under 6 px in radius; the misses there are "out of area/radius", "no
// candidate", "circularity" or "runs on", with the default colours as with calibrated ones).
// The colour calibration is judged on the balls it can matter for: within the 4 m that issue 9
// measures the range error in.
constexpr double kReachM = 4.0;
// A ball touching a line (every third one on these tours) is where colours and the detector
// meet: the dim tour's lines are not white to the default colours, so its balls merge with them;
// the automatic calibration fixes that, and the validation leaves the rays into a line, or into
// the feet of a person standing at the ball, out (validation.line_rays_unknown,
// validation.foreign_rays_unknown).

// The fitted config of the tour; its colours are the defaults.
Config startConfig(const OpticsCellFrames& rendered) { return rendered.fittedConfig; }

struct Tour {
    OpticsCell cell;
    OpticsCellFrames rendered;
    Geometry geometry;
};

// Whether the ball of frame f touches a field line (the simulator's field model), for the
// miss listing.
bool touchesLine(const OpticsCell& cell, int f)
{
    const OpticsCamera camera = opticsCellCamera(cell);
    const OpticsScene scene = opticsCellScene(cell, f, *camera.renderer);
    const FieldModel& field = camera.renderer->field();
    return field.distanceToLines(scene.ball) <= scene.ballRadius + 0.5 * field.dimensions().lineWidth + 0.02;
}

// The frames the colours are judged on: ball visible and within reach.
bool judged(const Tour& tour, int f)
{
    const auto t = tour.rendered.truth.find(f);
    return t != tour.rendered.truth.end() && t->second.ballVisible && std::hypot(t->second.xM, t->second.yM) <= kReachM;
}

Tour renderTour(OpticsLight light, OpticsCarpet carpet, BallKind ball, unsigned seed,
                OpticsDistractors distractors = OpticsDistractors::RobotsFeetShadow)
{
    OpticsCell cell;
    cell.distractors = distractors;
    cell.light = light;
    cell.carpet = carpet;
    cell.ball = ball;
    cell.frames = kFrames;
    cell.seed = seed;
    OpticsCellFrames r = renderCell(cell);
    Geometry g(r.fittedConfig.geometry, r.fittedConfig.mask);
    return Tour{cell, std::move(r), std::move(g)};
}

// Share of the ball frames within reach in which the detector finds the ball (Evaluation's
// rules).
double detectionPct(const Tour& tour, const Config& config)
{
    Pipeline pipeline(config);
    PipelineResult result;
    int withBall = 0;
    int correct = 0;
    for (std::size_t f = 0; f < tour.rendered.frames.size(); ++f) {
        if (!judged(tour, int(f))) continue;
        const TruthRow& truth = tour.rendered.truth.at(int(f));
        pipeline.process(tour.rendered.frames[f], PixelFormat::Bgr8, result);
        ++withBall;
        const bool ok = judge(outcomeOf(int(f), result), &truth) == TruthVerdict::Correct;
        correct += ok ? 1 : 0;
        if (!ok && qEnvironmentVariableIsSet("OMNITUNE_DEBUG_MISSES"))
            qInfo("  miss frame %d: %.1f m, r %.1f px%s: %s", int(f), std::hypot(truth.xM, truth.yM), truth.radiusPx,
                  touchesLine(tour.cell, int(f)) ? ", on a line" : "",
                  std::string(missCauseName(diagnoseMiss(result, truth, config.validation))).c_str());
    }
    return withBall > 0 ? 100.0 * correct / withBall : 0.0;
}

std::vector<cv::Mat> firstFrames(const Tour& tour, int n)
{
    return {tour.rendered.frames.begin(), tour.rendered.frames.begin() + std::min<std::ptrdiff_t>(n, tour.rendered.frames.size())};
}

// The ball's pixels well inside its silhouette on frame f (empty when it is hidden or tiny).
std::vector<cv::Point> ballCore(const Tour& tour, int f)
{
    const auto t = tour.rendered.truth.find(f);
    if (t == tour.rendered.truth.end() || !t->second.ballVisible || t->second.radiusPx < 4) return {};
    const TruthRow& row = t->second;
    return discPixels(cv::Point(int(std::lround(row.px)), int(std::lround(row.py))), int(row.radiusPx * 0.6),
                      tour.rendered.frames[std::size_t(f)].size());
}

// The carpet of frame f as the simulator knows it: the pixels that change when the same scene
// is rendered over a carpet of another colour (lines, robots, ball and body do not), less a
// 2 px rim where the optical blur mixes carpet and line.
cv::Mat carpetTruth(const Tour& tour, int f)
{
    const OpticsCamera camera = opticsCellCamera(tour.cell);
    OpticsScene scene = opticsCellScene(tour.cell, f, *camera.renderer);
    scene.carpet = cv::Vec3f(200, 40, 200);
    const cv::Mat other = camera.renderer->render(scene);
    cv::Mat diff;
    cv::absdiff(other, tour.rendered.frames[std::size_t(f)], diff);
    cv::Mat grey;
    cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
    cv::Mat carpet = grey > 20;
    cv::erode(carpet, carpet, cv::Mat(), cv::Point(-1, -1), 2);
    return carpet;
}

// The first enabled class with `role` (-1: none).
int classWithRole(const ColourClasses& classes, ColourRole role)
{
    for (std::size_t i = 0; i < classes.size(); ++i)
        if (classes[i].enabled && classes[i].role == role) return int(i);
    return -1;
}

// Share of `pixels` of frame f that the config's colours call class `index`.
double classShare(const Tour& tour, const Config& config, int f, const std::vector<cv::Point>& pixels, int index);

// What a user does after the automatic calibration, at most `strokes` times. First the ball:
// on the frame where the ball class holds least of the ball, brush the ball (its core, from the
// truth) into the first ball class, while that share is below 90 %. Then, on a frame where the
// detector still misses the ball, the carpet around it (carpetTruth) that no field class holds,
// into a new box of the first field class (Add box, then the stroke: a shadowed carpet tone
// gets a box of its own). Returns the strokes made.
int userStrokes(const Tour& tour, Config& config, int strokes)
{
    const int ball = classWithRole(config.colors.classes, ColourRole::Ball);
    const int field = classWithRole(config.colors.classes, ColourRole::Field);
    if (ball < 0 || field < 0) return 0;
    const cv::Mat used = tour.geometry.usedMask();
    int made = 0;
    auto brush = [&](int f, const std::vector<cv::Point>& pixels, int into, int box) {
        const ColourSamples samples = sampleColours(tour.rendered.frames[std::size_t(f)], PixelFormat::Bgr8, used, pixels);
        if (samples.hsv.empty()) return -1;
        ++made;
        return addSamples(config.colors.classes[std::size_t(into)].boxes, box, samples.hsv).box;
    };
    while (made < strokes) {
        int worst = -1;
        double worstShare = 0.9;
        for (int f = 0; f < int(tour.rendered.frames.size()); ++f) {
            const auto core = ballCore(tour, f);
            if (core.size() < 20 || !judged(tour, f)) continue;
            const double share = classShare(tour, config, f, core, ball);
            if (share < worstShare) worstShare = share, worst = f;
        }
        if (worst < 0 || brush(worst, ballCore(tour, worst), ball, 0) < 0) break;
    }
    int shadowBox = -1;
    for (std::size_t f = 0; f < tour.rendered.frames.size() && made < strokes; ++f) {
        if (!judged(tour, int(f))) continue;
        const TruthRow& truth = tour.rendered.truth.at(int(f));
        Pipeline pipeline(config);
        PipelineResult result;
        pipeline.process(tour.rendered.frames[f], PixelFormat::Bgr8, result);
        if (judge(outcomeOf(int(f), result), &truth) == TruthVerdict::Correct) continue;
        const ColourRoles roles(config.colors.classes);
        const cv::Mat carpet = carpetTruth(tour, int(f));
        std::vector<cv::Point> stroke;
        const cv::Point centre(int(std::lround(truth.px)), int(std::lround(truth.py)));
        for (const cv::Point& p : discPixels(centre, int(3 * std::max(4.0, truth.radiusPx)), carpet.size()))
            if (carpet.at<std::uint8_t>(p) && !roles.field(result.classes.at<std::uint8_t>(p))) stroke.push_back(p);
        if (stroke.size() < 10) continue;  // nothing of the carpet there is wrong
        const int box = brush(int(f), stroke, field,
                              shadowBox >= 0 ? shadowBox : int(config.colors.classes[std::size_t(field)].boxes.size()));
        if (box >= 0) shadowBox = box;
    }
    return made;
}

// Share of `pixels` of frame f that the config's colours call class `index`.
double classShare(const Tour& tour, const Config& config, int f, const std::vector<cv::Point>& pixels, int index)
{
    cv::Mat classes(tour.rendered.frames[std::size_t(f)].size(), CV_8UC1, cv::Scalar(0));
    ColorLut(config.colors).segment(tour.rendered.frames[std::size_t(f)], PixelFormat::Bgr8, tour.geometry.spans(), classes);
    int n = 0;
    for (const cv::Point& p : pixels) n += classes.at<std::uint8_t>(p) == int(colourClassId(index)) ? 1 : 0;
    return pixels.empty() ? 0.0 : double(n) / double(pixels.size());
}

}  // namespace

class ColourDoneWhenTest : public QObject {
    Q_OBJECT

    // Automatic calibration from the tour's first frames, then at most three strokes.
    void calibrateThenStroke(OpticsLight light, OpticsCarpet carpet, BallKind ball, unsigned seed)
    {
        const Tour tour = renderTour(light, carpet, ball, seed);
        QVERIFY2(tour.rendered.calibrationError.empty(), tour.rendered.calibrationError.c_str());
        Config config = startConfig(tour.rendered);
        QCOMPARE(config.colors.classes, defaultColourClasses());  // the start: the default colours
        const double before = detectionPct(tour, config);
        // The tour exercises the calibration: the default colours miss it (the dim one's goal).
        if (carpet == OpticsCarpet::Teal) QVERIFY2(before < kDoneWhenPct, qPrintable(QString::number(before)));

        const AutoColourResult r = autoColour(firstFrames(tour, kCalibrationFrames), tour.geometry, config.colors);
        QVERIFY2(r.ok(), r.error ? r.error->c_str() : "");
        config.colors = r.colors;
        QVERIFY(checkConfig(config).empty());
        const double afterAuto = detectionPct(tour, config);
        const int strokes = userStrokes(tour, config, 3);
        QVERIFY(checkConfig(config).empty());
        const double afterStrokes = detectionPct(tour, config);
        qInfo("%s: default colours %.0f %%, auto %.0f %% (carpet hue %d, V %d), after %d stroke(s) %.0f %%",
              opticsCellName(tour.cell).c_str(), before, afterAuto, r.carpetHue, r.carpetV, strokes, afterStrokes);
        QVERIFY2(afterStrokes >= kDoneWhenPct, qPrintable(QString::number(afterStrokes)));
        // Calibrating loses nothing the default colours find, give or take one frame: since
        // validation.run_on_colour_step the default colours find the dim tour's frame 27 (an
        // orange ball at 3.9 m on a line, unclassified by them), which the calibrated colours
        // classify as the ball, so the step does not apply, and still miss as "runs on".
        int frames = 0;
        for (std::size_t f = 0; f < tour.rendered.frames.size(); ++f) frames += judged(tour, int(f)) ? 1 : 0;
        const double oneFrame = frames > 0 ? 100.0 / frames : 0.0;
        QVERIFY2(afterStrokes >= before - oneFrame - 1e-9,
                 qPrintable(QString("%1 after strokes, %2 with the default colours").arg(afterStrokes).arg(before)));

        // The ball's pixels are the ball class on the frames of the tour where it is large enough
        // (90 %: where the user above stops brushing; the blurred rim stays out of the core).
        const int ballClass = classWithRole(config.colors.classes, ColourRole::Ball);
        QVERIFY(ballClass >= 0);
        double sum = 0;
        int n = 0;
        for (int f = 0; f < kFrames; ++f) {
            const auto pixels = ballCore(tour, f);
            if (pixels.size() < 20) continue;
            sum += classShare(tour, config, f, pixels, ballClass);
            ++n;
        }
        QVERIFY(n > 0);
        QVERIFY2(sum / n >= 0.9, qPrintable(QString::number(sum / n)));
    }

    void autoAlone(OpticsLight light, OpticsCarpet carpet, unsigned seed)
    {
        const Tour tour = renderTour(light, carpet, BallKind::Orange, seed);
        QVERIFY2(tour.rendered.calibrationError.empty(), tour.rendered.calibrationError.c_str());
        Config config = startConfig(tour.rendered);
        const double before = detectionPct(tour, config);
        const AutoColourResult r = autoColour(firstFrames(tour, kCalibrationFrames), tour.geometry, config.colors);
        QVERIFY2(r.ok(), r.error ? r.error->c_str() : "");
        config.colors = r.colors;
        const double after = detectionPct(tour, config);
        qInfo("%s: default colours %.0f %%, auto alone %.0f %%", opticsCellName(tour.cell).c_str(), before, after);
        QVERIFY2(after >= kDoneWhenPct, qPrintable(QString::number(after)));
        QVERIFY2(after >= before, qPrintable(QString::number(after)));
    }

private slots:
    void dimTourAutoThenStrokes() { calibrateThenStroke(OpticsLight::Dim, OpticsCarpet::Green, BallKind::Orange, 11); }
    // A cyan-green carpet past the default green box (hue ~89, in the default cyan marker box):
    // the default colours call most of it cyan.
    void cyanGreenCarpetAutoThenStrokes()
    {
        calibrateThenStroke(OpticsLight::Normal, OpticsCarpet::Teal, BallKind::Orange, 12);
    }
    void autoAloneOnDimTour() { autoAlone(OpticsLight::Dim, OpticsCarpet::Green, 21); }
    void autoAloneOnBrightTour() { autoAlone(OpticsLight::Bright, OpticsCarpet::Green, 22); }
};

QTEST_GUILESS_MAIN(ColourDoneWhenTest)
#include "calib_colour_done_when_test.moc"
