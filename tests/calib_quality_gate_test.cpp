// The quality gate (issue 9, section 5): the detector on the optics simulator's matrix of ball
// kinds x light x distractors x frame sizes (plus ball-free cells), with the config fitted from
// the simulated camera's measurements, against the floors in tests/quality_gate_floors.csv; and
// the same matrix read as the robot's IIDC camera delivers it (YUV 4:2:2) against
// tests/quality_gate_floors_uyvy.csv, whose figures differ (shared colour per pixel pair).
// The floors hold what the detector achieved when they were written (less a margin) and issue
// 9's targets; a run prints the measured table and the gap to each target, and fails naming
// every metric that fell below its floor.
//   OMNITUNE_GATE_FRAMES=N  frames per ball cell instead of the floors file's (slower, finer)
// An unoptimised or sanitizer build (CI's ASan + UBSan run, ~10x slower) runs a slice of one
// camera only, in BGR only, and checks that the run completes without asserting the floors (the
// normal build does); OMNITUNE_GATE_FULL=1 runs the whole matrix, both formats, there too.
// Regenerate the floors on purpose after a detector change:
//   build/app/omnitune-eval --quality-matrix --threads 0 --write-floors tests/quality_gate_floors.csv
//   build/app/omnitune-eval --quality-matrix --threads 0 --pixel-format uyvy --write-floors tests/quality_gate_floors_uyvy.csv
#include "calib/eval/QualityFloors.h"
#include "calib/eval/QualityReport.h"
#include "calib/fit/NumberCsv.h"
#include "core/ConfigSchema.h"

#include <QtTest>

#include <cstdlib>
#include <numeric>
#include <set>

using namespace omnitune;

namespace {

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define OMNITUNE_GATE_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
#define OMNITUNE_GATE_SANITIZED 1
#endif

bool fullMatrix()
{
#ifdef OMNITUNE_GATE_SANITIZED
    const char* env = std::getenv("OMNITUNE_GATE_FULL");
    return env && std::string(env) == "1";
#else
    return true;
#endif
}

const std::string kFloorsFile = OMNITUNE_SOURCE_DIR "/tests/quality_gate_floors.csv";
const std::string kUyvyFloorsFile = OMNITUNE_SOURCE_DIR "/tests/quality_gate_floors_uyvy.csv";
const std::string kDeviationsFile = OMNITUNE_SOURCE_DIR "/tests/quality_gate_deviations.csv";

}  // namespace

class QualityGateTest : public QObject {
    Q_OBJECT

    QualityFloorsFile floors_;
    QualityRun run_;
    std::vector<OpticsCell> cells_;  // what run_ ran
    QualityFloorsFile uyvyFloors_;
    QualityRun uyvyRun_;  // the full matrix read as UYVY (normal build only)
    bool full_ = true;

    // A floors file, parsed; fails the test naming the file when it cannot be read or parsed.
    static bool loadFloors(const std::string& path, QualityFloorsFile& out)
    {
        const auto text = readTextFile(path);
        if (!text) {
            QTest::qFail((path + " cannot be read").c_str(), __FILE__, __LINE__);
            return false;
        }
        std::string error;
        const auto floors = parseQualityFloors(*text, error);
        if (!floors) {
            QTest::qFail((path + ": " + error).c_str(), __FILE__, __LINE__);
            return false;
        }
        out = *floors;
        return true;
    }

    // The matrix a floors file was measured on, with OMNITUNE_GATE_FRAMES applied.
    static QualityMatrixOptions gateMatrix(const QualityFloorsFile& floors)
    {
        QualityMatrixOptions matrix = floors.matrix;
        if (const char* env = std::getenv("OMNITUNE_GATE_FRAMES")) matrix.framesPerCell = std::max(1, std::atoi(env));
        return matrix;
    }

    static QualityRun runGate(const std::vector<OpticsCell>& cells, PixelFormat format)
    {
        QualityRunOptions options;
        options.threads = 0;  // every hardware thread: the figures do not depend on it
        options.pixelFormat = format;
        const QualityRun run = runQuality(cells, algorithmVariants(), {}, options);
        const std::string md = qualitySummaryMarkdown(run, shippedVariants(run)) + "\n" +
                               qualityBreakdownMarkdown(run, shippedVariants(run));
        qInfo("%s frames, %zu cells, %d frames per ball cell\n%s", std::string(pixelFormatName(format)).c_str(),
              run.cells.size(), cells.empty() ? 0 : cells.front().frames, md.c_str());
        return run;
    }

private slots:
    void initTestCase()
    {
        if (const char* env = std::getenv("OMNITUNE_GATE_FRAMES"))
            QVERIFY2(std::atoi(env) >= 1, "OMNITUNE_GATE_FRAMES must be a positive whole number");
        if (!loadFloors(kFloorsFile, floors_) || !loadFloors(kUyvyFloorsFile, uyvyFloors_)) return;
        QCOMPARE(floors_.pixelFormat, PixelFormat::Bgr8);
        QCOMPARE(uyvyFloors_.pixelFormat, PixelFormat::Uyvy);
        cells_ = qualityMatrixCells(gateMatrix(floors_));
        full_ = fullMatrix();
        if (!full_) {
            // One camera (each costs a calibration, slow without optimisation): 640x480 without
            // rods, every third cell (balls, lights and distractors still all occur).
            std::vector<OpticsCell> slice;
            int k = 0;
            for (const OpticsCell& c : cells_)
                if (c.image.width == 640 && c.distractors != OpticsDistractors::RodsOcclusion && k++ % 3 == 0)
                    slice.push_back(c);
            cells_ = slice;
        }
        if (!full_) qInfo("a slice of the matrix, BGR only: unoptimised build");
        run_ = runGate(cells_, PixelFormat::Bgr8);
        if (full_) uyvyRun_ = runGate(qualityMatrixCells(gateMatrix(uyvyFloors_)), PixelFormat::Uyvy);
    }

    // Every ball kind meets every light and every distractor at both frame sizes, and the
    // ball-free cells are there to count false positives.
    void matrixCoversTheGrid()
    {
        const std::vector<OpticsCell> cells = qualityMatrixCells(floors_.matrix);
        std::set<std::string> names;
        int ballFree = 0;
        for (const OpticsCell& c : cells) {
            names.insert(opticsCellName(c));
            ballFree += !c.ballPresent;
        }
        QCOMPARE(int(names.size()), int(cells.size()));  // no cell twice
        QCOMPARE(int(cells.size()) - ballFree, int(kExtendedBallKinds.size()) * 4 * 4 * 2);
        QCOMPARE(ballFree, 4 * 4 * 2);
        // Every variant judged every frame of every cell it ran.
        QCOMPARE(run_.cells.size(), cells_.size());
        int frames = 0;
        for (const OpticsCell& c : cells_) frames += c.frames;
        for (std::size_t v = 0; v < run_.variants.size(); ++v) QCOMPARE(qualityTotal(run_, v).frames, frames);
    }

    // Each floors file holds every metric for every algorithm, so regenerating it cannot drop one.
    void floorsFileIsComplete()
    {
        for (const auto& [file, floors] : {std::pair{kFloorsFile, floors_}, std::pair{kUyvyFloorsFile, uyvyFloors_}}) {
            for (const QualityVariant& v : algorithmVariants())
                for (const char* metric : {"detection_pct", "cell_min_detection_pct", "false_positive_pct", "range_std_cm"}) {
                    const bool present = std::any_of(floors.floors.begin(), floors.floors.end(), [&](const QualityFloor& f) {
                        return f.algorithm == v.name && f.metric == metric;
                    });
                    QVERIFY2(present, (v.name + " " + metric + " has no row in " + file).c_str());
                }
            std::string error;
            const auto again = parseQualityFloors(serializeQualityFloors(floors), error);
            QVERIFY2(again.has_value(), error.c_str());
            QCOMPARE(serializeQualityFloors(*again), serializeQualityFloors(floors));
        }
    }

    // pixel_format names the frames the floors were measured on: absent means BGR (files written
    // before it), a format the detector does not read is refused with its line.
    void floorsPixelFormat()
    {
        const std::string rows = "algorithm,metric,bound,target,floor,measured\nspecific,detection_pct,min,97,80,82\n";
        std::string error;
        auto plain = parseQualityFloors("seed,3\n" + rows, error);
        QVERIFY2(plain.has_value(), error.c_str());
        QCOMPARE(plain->pixelFormat, PixelFormat::Bgr8);
        auto uyvy = parseQualityFloors("pixel_format,uyvy\nseed,3\n" + rows, error);
        QVERIFY2(uyvy.has_value(), error.c_str());
        QCOMPARE(uyvy->pixelFormat, PixelFormat::Uyvy);
        QCOMPARE(uyvy->matrix.seed, 3u);
        const std::string written = serializeQualityFloors(*uyvy);
        QVERIFY2(written.find("pixel_format,uyvy\n") != std::string::npos, written.c_str());
        QVERIFY2(written.find("--pixel-format uyvy --write-floors tests/quality_gate_floors_uyvy.csv") != std::string::npos,
                 written.c_str());
        QVERIFY(!parseQualityFloors("pixel_format,rgb24\n" + rows, error).has_value());
        QVERIFY2(error.find("line 1") != std::string::npos && error.find("rgb24") != std::string::npos, error.c_str());
    }

    // Each row of the deviations table switches a real key to a valid value other than ours.
    void deviationsTableApplies()
    {
        const auto text = readTextFile(kDeviationsFile);
        QVERIFY(text.has_value());
        std::string error;
        const std::vector<ConfigOverride> rows = parseDeviationsCsv(*text, error);
        QVERIFY2(error.empty(), error.c_str());
        QVERIFY(rows.size() >= 5);
        for (const ConfigOverride& o : rows) {
            Config c;
            QVERIFY(!applyConfigOverride(c, o).has_value());
            const ConfigKey* key = findConfigKey(o.key);
            QVERIFY(key);
            QVERIFY2(formatConfigValue(key->get(c)) != formatConfigValue(key->get(Config{})),
                     (o.key + ": the thesis value is already the default").c_str());
            QVERIFY(checkConfig(c).empty());
        }
        Config c;
        QVERIFY(applyConfigOverride(c, {"no.such_key", "1", ""}).has_value());
        QVERIFY(applyConfigOverride(c, {"validation.max_run_on_pct", "101", ""}).has_value());
        QVERIFY(applyConfigOverride(c, {"validation.first_edge_only", "maybe", ""}).has_value());
    }

    // The check itself, on a hand-made run: a metric below a min floor, or above a max floor,
    // fails; a metric that cannot be measured fails a floor; the gap to the target is named.
    void floorCheckFailsWhatFell()
    {
        QualityRun run;
        run.variants = {{"specific", Algorithm::Specific, {}}};
        QualityCellResult cell;
        cell.tallies.resize(1);
        cell.tallies[0].frames = 10;
        cell.tallies[0].withBall = 10;
        cell.tallies[0].correct = 8;
        cell.tallies[0].falsePositives = 1;
        run.cells = {cell};
        QualityFloorsFile file;
        file.floors = {{"specific", "detection_pct", true, 97.0, 81.0, {}},
                       {"specific", "detection_pct", true, 97.0, 79.0, {}},
                       {"specific", "false_positive_pct", false, 0.5, 5.0, {}},
                       {"specific", "range_std_cm", false, 5.0, 3.0, {}},
                       {"opencv", "detection_pct", true, 70.0, 1.0, {}}};  // not run: not checked
        const std::vector<QualityFloorCheck> checks = checkQualityFloors(run, file);
        QCOMPARE(int(checks.size()), 4);
        QVERIFY(!checks[0].passed);  // 80 < 81
        QVERIFY(checks[1].passed);
        QVERIFY2(checks[1].line.find("17.00 to go") != std::string::npos, checks[1].line.c_str());
        QVERIFY(!checks[2].passed);  // 10 % > 5 %
        QVERIFY(!checks[3].passed);  // no range sample to measure
    }

    // Every missed ball frame has one cause and every false positive one kind: the breakdown adds
    // up to the totals it explains.
    void missesAndFalsePositivesAddUp()
    {
        for (std::size_t v = 0; v < run_.variants.size(); ++v) {
            const QualityTally t = qualityTotal(run_, v);
            const int misses = std::accumulate(t.missCauses.begin(), t.missCauses.end(), 0);
            QCOMPARE(misses, t.withBall - t.correct);
            QVERIFY(t.missesRadiusOff <= misses);
            QVERIFY(t.missesPrefiltered <= misses);
            QCOMPARE(std::accumulate(t.falsePositiveKinds.begin(), t.falsePositiveKinds.end(), 0), t.falsePositives);
        }
        const std::string md = qualityMissesMarkdown(run_, shippedVariants(run_).back());
        QVERIFY2(md.find("| all ball cells | ") != std::string::npos, md.c_str());
        QVERIFY2(md.find("| distractors: rods | ") != std::string::npos || !full_, md.c_str());
        QVERIFY(qualityFalsePositivesMarkdown(run_, shippedVariants(run_)).find("| all |") != std::string::npos);
    }

    // A miss is blamed on the candidate at the ball that got farthest through validation.
    void missCauseIsTheFarthestTest()
    {
        TruthRow truth;
        truth.ballVisible = true;
        truth.px = 100;
        truth.py = 100;
        truth.radiusPx = 6;
        ValidationOptions v;
        PipelineResult r;
        QCOMPARE(diagnoseMiss(r, truth, v), MissCause::NoCandidate);
        BallCandidate far;
        far.x = 120;
        far.y = 100;
        far.rejected = RejectReason::NotChosen;
        r.candidates.push_back(far);
        QCOMPARE(diagnoseMiss(r, truth, v), MissCause::NoCandidate);  // 20 px away: not at the ball
        BallCandidate green;
        green.x = 103;
        green.y = 102;
        green.expectedRadiusPx = 6;
        green.rejected = RejectReason::NonGreen;
        r.candidates.push_back(green);
        QCOMPARE(diagnoseMiss(r, truth, v), MissCause::NonGreen);
        BallCandidate round = green;
        round.rejected = RejectReason::Circularity;
        round.scores.circularityPct = v.minCircularityPct - 1;
        round.expectedRadiusPx = 10;  // the model expects 10 px where the ball shows 6
        r.candidates.push_back(round);
        bool radiusOff = false;
        QCOMPARE(diagnoseMiss(r, truth, v, &radiusOff), MissCause::Circularity);
        QVERIFY(radiusOff);
        r.candidates.back().scores.circularityPct = v.minCircularityPct;  // the share passed: the fit failed
        QCOMPARE(diagnoseMiss(r, truth, v), MissCause::CircleOff);
        r.candidates.back().rejected = RejectReason::NotChosen;
        r.candidates.back().expectedRadiusPx = 6.5;
        QCOMPARE(diagnoseMiss(r, truth, v, &radiusOff), MissCause::LostToOther);
        QVERIFY(!radiusOff);
        r.candidates.back().rejected = RejectReason::None;
        QCOMPARE(diagnoseMiss(r, truth, v), MissCause::PositionOff);
    }

    // A false positive is placed at the rim, the body, beside the mask or in the field, and
    // blamed on the search that proposed it.
    void falsePositivePlaces()
    {
        Config config;  // centre (320, 240), radii 50..240
        PipelineResult r;
        BallCandidate c;
        c.source = CandidateSource::OpenCvHough;
        r.candidates.push_back(c);
        r.detection.found = true;
        r.detection.candidate = 0;
        r.detection.radiusPx = 6;
        auto at = [&](double x, double y) {
            r.detection.px = x;
            r.detection.py = y;
            return diagnoseFalsePositive(r, config);
        };
        QCOMPARE(at(320 + 235, 240).place, FalsePositivePlace::Rim);
        QCOMPARE(at(320 + 55, 240).place, FalsePositivePlace::Body);
        QCOMPARE(at(320 + 120, 240).place, FalsePositivePlace::Field);
        QCOMPARE(at(320 + 120, 240).source, CandidateSource::OpenCvHough);
        config.mask = cv::Mat(480, 640, CV_8UC1, cv::Scalar(255));
        config.mask.col(320 + 126).setTo(0);  // a rod 6 px beside the detection
        QCOMPARE(at(320 + 120, 240).place, FalsePositivePlace::Mask);
        QCOMPARE(at(320 + 100, 240).place, FalsePositivePlace::Field);
        for (std::size_t k = 0; k < kFalsePositiveKindCount; ++k)
            QCOMPARE(falsePositiveKindIndex(falsePositiveKindAt(k)), k);
    }

    // --cells: only the cells holding every part of the filter.
    void cellFilter()
    {
        const std::vector<OpticsCell> all = qualityMatrixCells(floors_.matrix);
        const std::vector<OpticsCell> some = filterOpticsCells(all, "dim,rods");
        QVERIFY(!some.empty());
        for (const OpticsCell& c : some) {
            QCOMPARE(c.light, OpticsLight::Dim);
            QCOMPARE(c.distractors, OpticsDistractors::RodsOcclusion);
        }
        int expected = 0;
        for (const OpticsCell& c : all) expected += c.light == OpticsLight::Dim && c.distractors == OpticsDistractors::RodsOcclusion;
        QCOMPARE(int(some.size()), expected);
        QCOMPARE(filterOpticsCells(all, "").size(), all.size());
        QVERIFY(filterOpticsCells(all, "dim,no-such-part").empty());
    }

    // --auto-colours: each cell's colours from Auto colours on frames of its own field (another
    // seed). On a carpet past the default green box the default colours lose balls (they take
    // the teal carpet for a robot's cyan marker, and find only the balls whose rays into it are
    // left out as occluded: 6 of 8 with marker_rays_unknown, none without); the calibrated ones
    // find them all, and the calibration never sees the judged frames' truth.
    void autoColoursCalibrateEachCell()
    {
        OpticsCell cell;
        cell.carpet = OpticsCarpet::Teal;
        cell.frames = 8;
        cell.seed = 7;
        QualityRunOptions options;
        const QualityTally byDefault = qualityTotal(runQuality({cell}, algorithmVariants(), {}, options), 0);
        options.autoColourFrames = 2;
        const QualityTally calibrated = qualityTotal(runQuality({cell}, algorithmVariants(), {}, options), 0);
        QCOMPARE(calibrated.withBall, byDefault.withBall);
        qInfo("teal carpet, specific: default colours %d, Auto colours %d of %d balls", byDefault.correct, calibrated.correct,
              calibrated.withBall);
        QVERIFY2(calibrated.correct == calibrated.withBall && calibrated.correct >= byDefault.correct + 2,
                 qPrintable(QString("%1 -> %2 of %3").arg(byDefault.correct).arg(calibrated.correct).arg(calibrated.withBall)));
    }

    // --pixel-format uyvy: the detector reads each rendered frame as an IIDC camera's YUV 4:2:2
    // (the robot's path: UYVY segmentation, noise estimate and blur). On noisy frames it must
    // find what BGR finds, give or take the pairs' shared colour at a small ball's border. The
    // conversion itself is calib/uyvy_encoding's test.
    void uyvyFramesAreReadAsTheRobotReadsThem()
    {
        OpticsCell cell;
        cell.distractors = OpticsDistractors::NoiseBlur;
        cell.frames = 8;
        cell.seed = 3;
        QualityRunOptions options;
        const QualityTally bgr = qualityTotal(runQuality({cell}, algorithmVariants(), {}, options), 0);
        options.pixelFormat = PixelFormat::Uyvy;
        const QualityTally uyvy = qualityTotal(runQuality({cell}, algorithmVariants(), {}, options), 0);
        qInfo("orange, noise, specific: BGR %d, UYVY %d of %d balls", bgr.correct, uyvy.correct, uyvy.withBall);
        QCOMPARE(uyvy.withBall, bgr.withBall);
        QVERIFY2(uyvy.correct >= bgr.correct - 1 && uyvy.correct >= uyvy.withBall - 2,
                 qPrintable(QString("BGR %1, UYVY %2 of %3").arg(bgr.correct).arg(uyvy.correct).arg(uyvy.withBall)));
        QCOMPARE(uyvy.falsePositives, 0);
    }

    void floors_data()
    {
        QTest::addColumn<bool>("uyvy");
        QTest::addColumn<QString>("algorithm");
        QTest::addColumn<QString>("metric");
        for (const QualityFloorsFile* file : {&floors_, &uyvyFloors_}) {
            const bool uyvy = file == &uyvyFloors_;
            for (const QualityFloor& f : file->floors)
                QTest::newRow((std::string(uyvy ? "uyvy " : "bgr8 ") + f.algorithm + " " + f.metric).c_str())
                    << uyvy << QString::fromStdString(f.algorithm) << QString::fromStdString(f.metric);
        }
    }

    void floors()
    {
        QFETCH(bool, uyvy);
        QFETCH(QString, algorithm);
        QFETCH(QString, metric);
        if (!full_) QSKIP("a slice of the matrix (unoptimised or sanitizer build): floors are asserted in the normal build");
        QualityFloorsFile one = uyvy ? uyvyFloors_ : floors_;
        one.floors.erase(std::remove_if(one.floors.begin(), one.floors.end(),
                                        [&](const QualityFloor& f) {
                                            return f.algorithm != algorithm.toStdString() || f.metric != metric.toStdString();
                                        }),
                         one.floors.end());
        const std::vector<QualityFloorCheck> checks = checkQualityFloors(uyvy ? uyvyRun_ : run_, one);
        QVERIFY2(!checks.empty(), "the floors file names an algorithm the gate does not run");
        for (const QualityFloorCheck& c : checks) {
            qInfo("%s", c.line.c_str());
            QVERIFY2(c.passed, c.line.c_str());
        }
    }
};

QTEST_GUILESS_MAIN(QualityGateTest)
#include "calib_quality_gate_test.moc"
