// Why the remounted camera finds fewer balls than the original one (issue 11's 12-point gap):
// the same ball positions on a 200-frame tour before and after the remount, each frame's miss
// cause (calib/eval/FrameDiagnosis) with both cameras' own full calibration, the ball as seen
// against the fitted ball model, how much of it the mask hides and where it sits in the ring.
//
// What it shows (OMNITUNE_REMOUNT_FRAMES=1 prints the table): the mirror raised 1 cm is farther
// from the camera, so its image is 10 % smaller (rim 232.7 -> 210.6 px, found within 0.02 px of
// the optics'), and the ring holds a whole ball out to 3.35 m instead of 4.32 m. Within 3.35 m
// both cameras find the same share (99.2 vs 97.6 %); beyond it the original finds 75 % and the
// remounted 48 % (validation.rim_test judges the balls the rim cuts; with every such ball
// refused it was 50.7 against 2.4 %: out of area at the rim, no candidate past the ring, the
// rest outside the mirror). The ball model follows the seen radii within 0.2 px, the
// centre the field's circles within 1 px: no calibration step is wrong, the optics see less.
#include "RemountScene.h"

#include "calib/eval/FrameDiagnosis.h"
#include "calib/fit/MeasuredCalibration.h"
#include "calib/sim/optics/OpticsMeasurement.h"
#include "core/BallModel.h"

#include <QtTest>

#include <array>

using namespace omnitune;
using namespace omnitune::remount;

namespace {

struct FrameRow {
    bool visible = false, correct = false;
    MissCause cause = MissCause::NoCandidate;
    double distanceM = 0, visibleShare = 0, radiusPx = 0, expectedPx = 0, ringPx = 0, maskedShare = 0;
};

// Share of the ball's disc that the config's mask leaves out.
double maskedShare(const Config& config, const TruthRow& t)
{
    if (config.mask.empty()) return 0;
    int all = 0, masked = 0;
    const int r = int(std::ceil(t.radiusPx));
    for (int y = int(t.py) - r; y <= int(t.py) + r; ++y)
        for (int x = int(t.px) - r; x <= int(t.px) + r; ++x) {
            if (std::hypot(x - t.px, y - t.py) > t.radiusPx || x < 0 || y < 0 || x >= config.mask.cols ||
                y >= config.mask.rows)
                continue;
            ++all;
            masked += config.mask.at<uchar>(y, x) == 0;
        }
    return all ? double(masked) / all : 0;
}

std::vector<FrameRow> diagnose(const Tour& tour, const Config& config)
{
    Pipeline pipeline(config);
    PipelineResult result;
    const BallModel model(config.ball);
    std::vector<FrameRow> rows;
    for (int i = 0; i < int(tour.frames.size()); ++i) {
        pipeline.process(tour.frames[i], PixelFormat::Bgr8, result);
        const TruthRow& t = tour.truth.at(i);
        FrameRow row;
        row.visible = t.ballVisible;
        row.distanceM = tour.optics[i].distanceM;
        row.visibleShare = tour.optics[i].visibleFraction;
        if (t.ballVisible) {
            const double d = std::hypot(t.px - config.geometry.centerX, t.py - config.geometry.centerY);
            row.radiusPx = t.radiusPx;
            row.expectedPx = model.radiusAt(d);
            row.ringPx = d;
            row.maskedShare = maskedShare(config, t);
            row.correct = judge(outcomeOf(i, result), &t) == TruthVerdict::Correct;
            if (!row.correct) row.cause = diagnoseMiss(result, t, config.validation);
        }
        rows.push_back(row);
    }
    return rows;
}

QString describe(const FrameRow& r)
{
    if (!r.visible) return QString("hidden (%1 visible)").arg(r.visibleShare, 0, 'f', 2);
    return QString("%1 d=%2px r=%3/%4px masked=%5")
        .arg(r.correct ? QStringLiteral("found") : QString::fromUtf8(missCauseName(r.cause).data()), -12)
        .arg(r.ringPx, 5, 'f', 1)
        .arg(r.radiusPx, 4, 'f', 1)
        .arg(r.expectedPx, 4, 'f', 1)
        .arg(r.maskedShare, 4, 'f', 2);
}

// Misses by cause over `rows` whose ball lies within `maxM` (or beyond it when `beyond`).
struct Tally {
    int visible = 0, found = 0;
    std::array<int, kMissCauseCount> causes{};
    double ratio() const { return visible ? 100.0 * found / visible : 0.0; }
};
Tally tally(const std::vector<FrameRow>& rows, double maxM, bool beyond = false)
{
    Tally t;
    for (const FrameRow& r : rows) {
        if (!r.visible || (r.distanceM > maxM) != beyond) continue;
        ++t.visible;
        if (r.correct)
            ++t.found;
        else
            ++t.causes[std::size_t(r.cause)];
    }
    return t;
}
QString causes(const Tally& t)
{
    QStringList parts;
    for (std::size_t c = 0; c < kMissCauseCount; ++c)
        if (t.causes[c]) parts << QString("%1 %2").arg(QString::fromUtf8(missCauseName(MissCause(c)).data())).arg(t.causes[c]);
    return QString("%1/%2 = %3 %; misses: %4").arg(t.found).arg(t.visible).arg(t.ratio(), 0, 'f', 1).arg(parts.join(", "));
}

// The farthest ground distance of a ball whose circle (as seen) lies inside the config's ring:
// beyond it the detector does not look (its ring ends at outer_radius).
double ringReachM(const std::vector<FrameRow>& rows, const Config& c)
{
    double reach = 0;
    for (const FrameRow& r : rows)
        if (r.visible && r.ringPx + r.radiusPx <= c.geometry.outerRadius) reach = std::max(reach, r.distanceM);
    return reach;
}

}  // namespace

class RemountDiagnosisTest : public QObject {
    Q_OBJECT
private slots:
    void gapExplained()
    {
        OpticsCell cell = tourCell();
        cell.frames = 200;  // one ball in 200 is half a point: the 2-point bound needs that resolution
        const CatadioptricCamera originalCamera(originalMount(cell));
        const OpticsRenderer originalRenderer(originalCamera);
        const MeasuredCalibration c0 = calibrateFromMeasurements(Config{}, measureOpticsCamera(originalRenderer));
        QVERIFY(c0.ok());
        const CatadioptricCamera camera(remounted(originalMount(cell)));
        const OpticsRenderer renderer(camera);
        const MeasuredCalibration c1 = calibrateFromMeasurements(Config{}, measureOpticsCamera(renderer));
        QVERIFY(c1.ok());
        const std::vector<FrameRow> before = diagnose(renderTour(cell, originalRenderer), c0.config);
        const std::vector<FrameRow> after = diagnose(renderTour(cell, renderer), c1.config);
        const GeometryOptions &g0 = c0.config.geometry, &g1 = c1.config.geometry;
        qInfo().noquote() << QString("rim before %1 px at (%2, %3), outer %4; after %5 px at (%6, %7), outer %8; the "
                                     "optics' rims: %9 px at (%10, %11), %12 px at (%13, %14)")
                                 .arg(c0.rim.rimRadius).arg(g0.centerX).arg(g0.centerY).arg(g0.outerRadius)
                                 .arg(c1.rim.rimRadius).arg(g1.centerX).arg(g1.centerY).arg(g1.outerRadius)
                                 .arg(originalCamera.rimRadiusPx()).arg(originalCamera.rimCentre().x)
                                 .arg(originalCamera.rimCentre().y).arg(camera.rimRadiusPx()).arg(camera.rimCentre().x)
                                 .arg(camera.rimCentre().y);
        // The fitted centre is where the field's circles are centred (what the distance map
        // needs), within 1 px; the mirror rim's own mean lies ~2 px off it on both cameras.
        QVERIFY(cv::norm(cv::Point2d(g0.centerX, g0.centerY) - fieldCentre(originalCamera)) < 1.0);
        QVERIFY(cv::norm(cv::Point2d(g1.centerX, g1.centerY) - fieldCentre(camera)) < 1.0);
        const double reach0 = ringReachM(before, c0.config), reach1 = ringReachM(after, c1.config);
        qInfo().noquote() << QString("a whole ball inside the ring out to %1 m before, %2 m after").arg(reach0).arg(reach1);
        if (qEnvironmentVariableIsSet("OMNITUNE_REMOUNT_FRAMES"))  // the per-frame table
            for (std::size_t i = 0; i < before.size(); ++i)
                qInfo().noquote() << QString("%1 %2 m  before %3 | after %4").arg(i, 3).arg(before[i].distanceM, 4, 'f', 2)
                                         .arg(describe(before[i]), -60).arg(describe(after[i]));
        const Tally all0 = tally(before, 1e9), all1 = tally(after, 1e9);
        const Tally in0 = tally(before, reach1), in1 = tally(after, reach1);
        const Tally out0 = tally(before, reach1, true), out1 = tally(after, reach1, true);
        qInfo().noquote() << "whole tour   before" << causes(all0) << "| after" << causes(all1);
        qInfo().noquote() << "within" << reach1 << "m before" << causes(in0) << "| after" << causes(in1);
        qInfo().noquote() << "beyond" << reach1 << "m before" << causes(out0) << "| after" << causes(out1);
        // The raised mirror is farther from the camera: its image is ~10 % smaller, so the ring
        // reaches less far onto the field (the optics, not a fit: the rim is found within 1 px).
        QVERIFY(c1.rim.rimRadius < 0.93 * c0.rim.rimRadius);
        QVERIFY(reach1 < reach0 - 0.5);
        // The whole-tour gap comes from the balls beyond the remounted ring's reach: there the
        // remounted camera misses nearly all (out of area at the rim, no candidate past it)...
        // (validation.rim_test judges balls cut by the rim: beyond the reach the original camera
        // finds 75 %, the remounted 48 %; 51 and 2 % with every such ball refused.)
        QVERIFY2(out1.ratio() < out0.ratio() - 20, qPrintable(causes(out0) + " | " + causes(out1)));
        const int rimMisses = out1.causes[std::size_t(MissCause::OutOfRange)] + out1.causes[std::size_t(MissCause::NoCandidate)];
        QVERIFY2(rimMisses >= (out1.visible - out1.found) * 9 / 10, qPrintable(causes(out1)));
        // ...and within it the two cameras find the same share of balls, within 2 points.
        QVERIFY2(std::abs(in1.ratio() - in0.ratio()) <= 2.0, qPrintable(causes(in0) + " | " + causes(in1)));
    }
};

QTEST_GUILESS_MAIN(RemountDiagnosisTest)
#include "calib_remount_diagnosis_test.moc"
