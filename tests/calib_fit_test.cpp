// The geometry fits of calib/fit/: each recovers a known curve or circle from noisy synthetic
// data drawn here with a seeded RNG, refuses what it cannot fit with the right kind, and on the
// demo session recovers the geometry and ball model its config.yml was rendered with.
#include "calib/fit/BallModelFit.h"
#include "calib/fit/BallSamplesCsv.h"
#include "calib/fit/BodyFit.h"
#include "calib/fit/CalibrationPointsCsv.h"
#include "calib/fit/CircleFit.h"
#include "calib/fit/DistanceMapFit.h"
#include "calib/fit/Polynomial.h"
#include "calib/fit/RimFit.h"
#include "calib/session/SessionReader.h"
#include "calib/sim/SceneSimulator.h"
#include "core/ConfigParser.h"
#include "core/Pi.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <cmath>
#include <random>

using namespace omnitune;

Q_DECLARE_METATYPE(cv::Size)
Q_DECLARE_METATYPE(cv::Point2d)

namespace {

const std::string kDemo = std::string(OMNITUNE_SOURCE_DIR) + "/sessions/demo";

// A mirror camera frame drawn from scratch: dark housing outside a disc of radius `rim` (edge
// antialiased by 4x4 supersampling), textured carpet inside that moves with `shift`, white
// lines, a dark robot body of radius `body` in the middle and a black obstacle touching the rim
// (its rays give false rim points the robust fit must drop). Sensor noise sigma 2.
cv::Mat drawMirrorFrame(cv::Size size, cv::Point2d c, double rim, double body, double shift, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 2.0);
    cv::Mat img(size, CV_8UC3);
    for (int y = 0; y < size.height; ++y) {
        for (int x = 0; x < size.width; ++x) {
            // Coverage of the mirror disc over the pixel's area.
            double inside = 0;
            const double rho = std::hypot(x - c.x, y - c.y);
            if (rho < rim - 1.5) inside = 1;
            else if (rho <= rim + 1.5)
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j)
                        inside += (std::hypot(x - 0.375 + 0.25 * i - c.x, y - 0.375 + 0.25 * j - c.y) < rim) / 16.0;
            // The field as the robot drives: texture and lines slide with `shift`.
            const double u = x + shift;
            const double v = y + 0.6 * shift;
            double g = 120 + 25 * std::sin(u * 0.07) * std::cos(v * 0.05);
            if (std::abs(std::fmod(u + 1000, 90.0) - 45) < 3) g = 230;  // white lines
            const double angle = std::atan2(y - c.y, x - c.x);
            if (rho > rim - 40 && std::abs(angle - 0.8) < 0.12) g = 15;  // obstacle touching the rim
            if (rho < body) g = std::abs(std::sin(3 * angle)) < 0.15 ? 30 : 55;  // robot body, spokes
            const double value = inside * g + (1 - inside) * 8 + noise(rng);
            const auto b = cv::saturate_cast<std::uint8_t>(value);
            img.at<cv::Vec3b>(y, x) = {cv::saturate_cast<std::uint8_t>(0.6 * b), b, cv::saturate_cast<std::uint8_t>(0.5 * b)};
        }
    }
    return img;
}

std::vector<cv::Mat> mirrorFrames(cv::Size size, cv::Point2d c, double rim, double body, int count)
{
    std::vector<cv::Mat> frames;
    for (int i = 0; i < count; ++i) frames.push_back(drawMirrorFrame(size, c, rim, body, 37.0 * i, 100u + unsigned(i)));
    return frames;
}

// Records the last percentage; asks to cancel once it has passed `cancelAt`.
class RecordingProgress : public Progress {
public:
    explicit RecordingProgress(double cancelAt = 1000) : cancelAt_(cancelAt) {}
    void update(double percent) override { last = percent; }
    bool isCancelRequested() const override { return last >= cancelAt_; }
    double last = -1;

private:
    double cancelAt_;
};

}  // namespace

class CalibFitTest : public QObject {
    Q_OBJECT

private slots:
    void circleDropsOutliers()
    {
        std::mt19937 rng(7);
        std::normal_distribution<double> noise(0.0, 0.3);
        std::uniform_real_distribution<double> inward(20.0, 120.0);
        std::vector<cv::Point2d> pts;
        // A partial arc (as a mirror cut by the frame leaves) plus 25 % points pulled inwards.
        for (int i = 0; i < 200; ++i) {
            const double a = -1.2 + 2.4 * i / 199.0 + (i % 2 ? kPi : 0.0);
            const double r = 210.0 + (i % 4 == 0 ? -inward(rng) : noise(rng));
            pts.push_back({311.4 + r * std::cos(a), 228.9 + r * std::sin(a)});
        }
        const CircleFit fit = fitCircle(pts);
        QVERIFY(fit.ok);
        QVERIFY2(std::abs(fit.centre.x - 311.4) < 0.2 && std::abs(fit.centre.y - 228.9) < 0.2,
                 qPrintable(QString("centre %1 %2").arg(fit.centre.x).arg(fit.centre.y)));
        QVERIFY(std::abs(fit.radius - 210.0) < 0.2);
        QCOMPARE(fit.inliers, 150);
        QVERIFY(fit.rms < 0.5);
    }

    void polynomialRecoversCubic()
    {
        const std::vector<double> truth = {0.2, -0.01, 3e-4, -4e-7};
        std::vector<double> x, y;
        for (int i = 0; i <= 40; ++i) {
            x.push_back(50 + 5.0 * i);
            y.push_back(evaluatePolynomial(truth, x.back()));
        }
        const auto c = fitPolynomial(x, y, 3);
        QCOMPARE(int(c.size()), 4);
        for (double at : {50.0, 120.0, 250.0}) QVERIFY(std::abs(evaluatePolynomial(c, at) - evaluatePolynomial(truth, at)) < 1e-9);
        QVERIFY(std::abs(evaluateDerivative(c, 100.0) - (-0.01 + 2 * 3e-4 * 100 - 3 * 4e-7 * 1e4)) < 1e-9);
    }

    // A mirror-like map: slow near the robot, fast towards the horizon; 2 cm measurement noise.
    void distanceMapRecoversCurve()
    {
        const auto truth = [](double r) { return 0.004 * r + 2.2e-7 * r * r * r; };
        std::mt19937 rng(11);
        std::normal_distribution<double> noise(0.0, 0.02);
        std::vector<DistancePoint> pts;
        for (int i = 0; i < 20; ++i) {
            const double r = 60 + 9.0 * i;
            pts.push_back({r, truth(r) + noise(rng), i + 2});
        }
        const DistanceMapFitResult result = fitDistanceMap(pts);
        QVERIFY2(result.ok(), result.ok() ? "" : result.error->message.c_str());
        const DistanceMapFit& f = result.fit;
        QVERIFY(f.rmsCm > 0.5 && f.rmsCm < 3.0);  // about the noise
        QCOMPARE(int(f.residualsCm.size()), 20);
        QCOMPARE(int(f.tableRadiiPx.size()), 16);
        QCOMPARE(f.tableRadiiPx.front(), 60.0);
        QCOMPARE(f.tableRadiiPx.back(), 231.0);
        QVERIFY(f.tableDeviationCm < 0.5);
        // The table as the detector reads it gives the true curve back within 2 cm.
        DistanceMapOptions options;
        applyDistanceMapFit(f, options);
        const DistanceMap map(options);
        for (double r = 60; r <= 231; r += 3.0)
            QVERIFY2(std::abs(map.toGround(r) - truth(r)) < 0.02, qPrintable(QString("at %1 px: %2 vs %3").arg(r).arg(map.toGround(r)).arg(truth(r))));
    }

    void distanceMapRefusesBendingFit()
    {
        // Rises, then falls: a mis-typed distance at the end.
        const std::vector<DistancePoint> pts = {{60, 0.3, 2},  {90, 0.6, 3},  {120, 1.0, 4},
                                                {150, 1.6, 5}, {180, 2.5, 6}, {210, 1.2, 7}};
        const DistanceMapFitResult result = fitDistanceMap(pts);
        QVERIFY(!result.ok());
        QCOMPARE(int(result.error->kind), int(FitErrorKind::NotMonotone));
        QVERIFY2(result.error->message.find("bends back at") != std::string::npos, result.error->message.c_str());
        QVERIFY2(result.error->message.find("line 7") != std::string::npos, result.error->message.c_str());
    }

    // A mirror whose metres per pixel run away near the rim (the spherical one): no polynomial
    // of degree 1..6 rises over the marks, so the map is the marks' own table, monotone.
    void distanceMapFallsBackToThePointsTable()
    {
        std::vector<DistancePoint> pts;
        for (int i = 0; i < 40; ++i) {
            const double r = 60 + 4 * i;
            pts.push_back({r, r < 180 ? 0.01 * r : 1.8 + 0.3 * (r - 180), i + 2});
        }
        const DistanceMapFitResult result = fitDistanceMap(pts);
        QVERIFY2(result.ok(), result.ok() ? "" : result.error->message.c_str());
        QVERIFY(result.fit.pointsTable);
        QVERIFY(result.fit.note.find("no polynomial") != std::string::npos);
        QVERIFY(result.fit.rmsCm < 0.5);
        DistanceMapOptions options;
        applyDistanceMapFit(result.fit, options);
        const DistanceMap map(options);
        for (double r = 61; r < 215; r += 2) QVERIFY(map.toGround(r + 1) > map.toGround(r));
    }

    // Marks laid 5 cm apart close against the body, in several directions: the radius of a
    // farther one is now and then a pixel or two below a nearer one's (the centre is off by that
    // in some direction). The table pools such neighbours instead of refusing the marks.
    void distanceMapTablePoolsScatteredMarks()
    {
        std::vector<DistancePoint> pts;
        for (int i = 0; i < 60; ++i) {
            const double r = 60 + 2.5 * i;
            const double d = r < 180 ? 0.01 * r : 1.8 + 0.3 * (r - 180);
            const double scatter = r < 150 ? (i % 2 ? -2.25 : 2.25) : 0.0;  // an odd mark 2 px inside the even one
            pts.push_back({r + scatter, d, i + 2});
        }
        const DistanceMapFitResult result = fitDistanceMap(pts);
        QVERIFY2(result.ok(), result.ok() ? "" : result.error->message.c_str());
        QVERIFY(result.fit.pointsTable);
        QVERIFY2(result.fit.rmsCm < 2.0, qPrintable(QString("RMS %1 cm").arg(result.fit.rmsCm)));
        DistanceMapOptions options;
        applyDistanceMapFit(result.fit, options);
        const DistanceMap map(options);
        for (double r = 61; r < 205; r += 2) QVERIFY(map.toGround(r + 1) > map.toGround(r));
    }

    void distanceMapRefusesTooFewPoints()
    {
        const std::vector<DistancePoint> pts = {{60, 0.3}, {90, 0.6}, {120, 1.0}, {150, 1.6}};
        const DistanceMapFitResult result = fitDistanceMap(pts);  // degree 3 needs 5
        QVERIFY(!result.ok());
        QCOMPARE(int(result.error->kind), int(FitErrorKind::TooFewPoints));
        QVERIFY(result.error->message.find("at least 5 points") != std::string::npos);
        DistanceMapFitOptions linear;
        linear.degree = 1;
        QVERIFY(fitDistanceMap(pts, linear).ok());
    }

    void pointsCsvParses()
    {
        const CalibrationPointsParse a = parseCalibrationPoints(
            "# floor marks\nradius_px,distance_m\n60,0.3\n\n90,0,5\n120,abc\n150,1.6\n-3,1\n", "p.csv");
        QVERIFY(a.ok());
        QCOMPARE(int(a.points.size()), 2);
        QCOMPARE(a.points[1].line, 7);
        QCOMPARE(a.points[1].radiusPx, 150.0);
        QVERIFY(!a.needsCentre());
        QCOMPARE(int(a.warnings.size()), 3);
        QCOMPARE(int(a.warnings[0].kind), int(CsvIssueKind::WrongColumnCount));
        QCOMPARE(a.warnings[0].toString(), std::string("p.csv:5: 3 cells where the header has 2; row skipped"));
        QCOMPARE(int(a.warnings[1].kind), int(CsvIssueKind::BadNumber));
        QCOMPARE(a.warnings[1].line, 6);
        QCOMPARE(int(a.warnings[2].kind), int(CsvIssueKind::BadValue));

        const CalibrationPointsParse b = parseCalibrationPoints("distance_m,x,y,note\n1.5,420,240,a\n2,320,40,b\n", "q.csv");
        QVERIFY(b.ok());
        QVERIFY(b.needsCentre());
        QCOMPARE(int(b.warnings.size()), 1);
        QCOMPARE(int(b.warnings[0].kind), int(CsvIssueKind::UnknownColumn));
        const auto pts = toDistancePoints(b.points, {320, 240});
        QCOMPARE(pts[0].radiusPx, 100.0);
        QCOMPARE(pts[1].radiusPx, 200.0);
        QCOMPARE(pts[1].distanceM, 2.0);

        const CalibrationPointsParse c = parseCalibrationPoints("60,0.3\n90,0.6\n", "r.csv");
        QVERIFY(!c.ok());
        QCOMPARE(int(c.error->kind), int(CsvIssueKind::MissingColumn));
        QCOMPARE(c.error->line, 1);
        QVERIFY(c.warnings.empty());  // no "unknown column '60'" for a missing header
        QVERIFY(!loadCalibrationPoints("/nonexistent/points.csv").ok());
    }

    void ballModelRecoversQuadratic()
    {
        const BallModelOptions truth;  // the thesis' curve
        const BallModel model(truth);
        std::mt19937 rng(5);
        std::normal_distribution<double> noise(0.0, 0.3);
        std::uniform_real_distribution<double> where(75.0, 235.0);
        std::vector<BallSample> samples;
        for (int i = 0; i < 40; ++i) {
            const double d = where(rng);
            samples.push_back({d, model.radiusAt(d) + noise(rng), i, std::nullopt});
        }
        const BallModelFitResult result = fitBallModel(samples);
        QVERIFY(result.ok());
        for (double d = 80; d <= 230; d += 10)
            QVERIFY2(std::abs(result.fit.radiusAt(d) - model.radiusAt(d)) < 0.25,
                     qPrintable(QString("at %1 px: %2 vs %3").arg(d).arg(result.fit.radiusAt(d)).arg(model.radiusAt(d))));
        QVERIFY(result.fit.rmsPx > 0.2 && result.fit.rmsPx < 0.4);
        BallModelOptions written;
        applyBallModelFit(result.fit, written);
        QCOMPARE(written.c0, result.fit.c0);
        QCOMPARE(written.c2, result.fit.c2);
    }

    // A camera whose near balls look bigger than ball.max_radius (25 px): applying the fit
    // raises the bound so that r(d) is not clamped where balls were measured; a fit inside
    // the bound leaves it.
    void ballModelKeepsMeasuredRadiiUnclamped()
    {
        std::vector<BallSample> samples;
        for (int i = 0; i < 20; ++i) {
            const double d = 40.0 + 8.0 * i;
            samples.push_back({d, 34.0 - 0.12 * d, i, std::nullopt});  // 29.2 px at 40 px
        }
        const BallModelFitResult result = fitBallModel(samples);
        QVERIFY(result.ok());
        BallModelOptions written;
        QCOMPARE(written.maxRadius, 25.0);
        applyBallModelFit(result.fit, written);
        QVERIFY2(written.maxRadius >= 29.2, qPrintable(QString::number(written.maxRadius)));
        QVERIFY(std::abs(BallModel(written).radiusAt(40.0) - 29.2) < 0.05);

        BallModelOptions thesis;
        const BallModel model(thesis);
        std::vector<BallSample> inside;
        for (int i = 0; i < 20; ++i) inside.push_back({80.0 + 8.0 * i, model.radiusAt(80.0 + 8.0 * i), i, std::nullopt});
        BallModelOptions kept;
        applyBallModelFit(fitBallModel(inside).fit, kept);
        QCOMPARE(kept.maxRadius, 25.0);
    }

    // An off-axis mirror: the ball 8 % bigger towards 60 deg. The fit recovers the term, offers
    // it, and core/BallModel evaluates what it writes; on-axis samples get no offer.
    void ballModelRecoversOffAxisTerm()
    {
        BallModelOptions truth;  // the thesis' curve with a known per-direction term
        truth.directionCos = 0.08 * std::cos(60 * CV_PI / 180);
        truth.directionSin = 0.08 * std::sin(60 * CV_PI / 180);
        truth.maxRadius = 100;
        const BallModel model(truth);
        std::mt19937 rng(9);
        std::normal_distribution<double> noise(0.0, 0.2);
        std::uniform_real_distribution<double> where(75.0, 235.0), angle(-CV_PI, CV_PI);
        std::vector<BallSample> offAxis, onAxis;
        for (int i = 0; i < 60; ++i) {
            const double d = where(rng), a = angle(rng), n = noise(rng);
            offAxis.push_back({d, model.radiusAt(d, a) + n, i, a});
            onAxis.push_back({d, model.radiusAt(d) + n, i, a});
        }
        const BallModelFitResult result = fitBallModel(offAxis);
        QVERIFY(result.ok());
        QVERIFY(result.fit.direction);
        QVERIFY2(result.fit.directionOffered, result.fit.directionNote.c_str());
        const BallModelFit::Direction& dir = *result.fit.direction;
        QVERIFY2(std::abs(dir.cosTerm - truth.directionCos) < 0.01 && std::abs(dir.sinTerm - truth.directionSin) < 0.01,
                 qPrintable(QString("%1, %2").arg(dir.cosTerm).arg(dir.sinTerm)));
        QVERIFY(dir.rmsPx < 0.3 && result.fit.rmsPx > 0.5);  // the radial fit alone cannot follow it
        BallModelOptions written;
        written.maxRadius = 100;
        applyBallModelFit(result.fit, written, true);
        const BallModel fitted(written);
        for (double d = 95; d <= 215; d += 30)  // inside the samples' span, away from its ends
            for (double a = -3; a <= 3; a += 1)
                QVERIFY2(std::abs(fitted.radiusAt(d, a) - model.radiusAt(d, a)) < 0.2,
                         qPrintable(QString("at %1 px, %2 rad: %3 vs %4").arg(d).arg(a).arg(fitted.radiusAt(d, a)).arg(model.radiusAt(d, a))));
        // Without the term: written back as 0 and 0, and the angle changes nothing, bit for bit.
        applyBallModelFit(result.fit, written);
        QCOMPARE(written.directionCos, 0.0);
        QCOMPARE(written.directionSin, 0.0);
        const BallModel radial(written);
        for (double d = 80; d <= 230; d += 30) QCOMPARE(radial.radiusAt(d, 1.3), radial.radiusAt(d));
        QCOMPARE(radial.squareSizeAt(150, 1.3), radial.squareSizeAt(150));

        const BallModelFitResult plain = fitBallModel(onAxis);
        QVERIFY(plain.ok());
        QVERIFY2(!plain.fit.directionOffered, plain.fit.directionNote.c_str());
        // Samples from one side only cannot tell a direction from a distance.
        std::vector<BallSample> oneSide = offAxis;
        for (BallSample& s : oneSide) s.angleRad = 0.3 * *s.angleRad / CV_PI;
        QVERIFY(!fitBallModel(oneSide).fit.direction);
    }

    void ballModelRefusesTooLittle()
    {
        std::vector<BallSample> few = {{100, 15}, {140, 11}, {180, 7}};
        const auto a = fitBallModel(few);
        QVERIFY(!a.ok());
        QCOMPARE(int(a.error->kind), int(FitErrorKind::TooFewPoints));
        std::vector<BallSample> narrow;
        for (int i = 0; i < 10; ++i) narrow.push_back({150.0 + i, 10.0 - 0.1 * i});
        const auto b = fitBallModel(narrow);
        QVERIFY(!b.ok());
        QCOMPARE(int(b.error->kind), int(FitErrorKind::NarrowSpan));
        QVERIFY(b.error->message.find("near the robot and far away") != std::string::npos);
    }

    void ballSamplesCsvParses()
    {
        const BallSamplesParse a = parseBallSamples("radius_px,distance_px\n12.5,100\n+9,150.5\n7;200\n3,-1\n", "s.csv");
        QVERIFY(a.ok());
        QVERIFY(!a.needsDistanceMap());
        QCOMPARE(int(a.rows.size()), 2);
        QCOMPARE(a.rows[1].distance, 150.5);
        QCOMPARE(a.rows[1].radiusPx, 9.0);
        QCOMPARE(int(a.warnings.size()), 2);
        QCOMPARE(a.warnings[0].toString(), std::string("s.csv:4: 1 cells where the header has 2; row skipped"));
        QCOMPARE(int(a.warnings[1].kind), int(CsvIssueKind::BadValue));

        // Ground distances go through the distance map, ball-height corrected.
        const BallSamplesParse b = parseBallSamples("# ball laid out at measured distances\ndistance_m,radius_px\n1.0,14\n", "m.csv");
        QVERIFY(b.ok());
        QVERIFY(b.needsDistanceMap());
        const DistanceMap map{DistanceMapOptions{}};
        const auto samples = toBallSamples(b.rows, map);
        QCOMPARE(samples[0].distancePx, map.ballPixels(1.0));
        QCOMPARE(samples[0].radiusPx, 14.0);

        const BallSamplesParse c = parseBallSamples("distance,radius\n1,2\n", "x.csv");
        QVERIFY(!c.ok());
        QCOMPARE(int(c.error->kind), int(CsvIssueKind::MissingColumn));
        QVERIFY(!loadBallSamples("/nonexistent/s.csv").ok());
    }

    void ballSamplesFromTruthRows()
    {
        std::map<int, TruthRow> truth;
        const auto row = [](int frame, bool visible, double x, double y, double r) {
            TruthRow t;
            t.frame = frame;
            t.ballVisible = visible;
            t.px = x;
            t.py = y;
            t.radiusPx = r;
            return t;
        };
        truth[3] = row(3, true, 420, 240, 9.5);
        truth[4] = row(4, false, 0, 0, 0);
        truth[5] = row(5, true, 320, 90, 7.0);
        const auto s = ballSamplesFromTruth(truth, {320, 240});
        QCOMPARE(int(s.size()), 2);
        QCOMPARE(s[0].distancePx, 100.0);
        QCOMPARE(s[0].frame, 3);
        QCOMPARE(s[1].distancePx, 150.0);
        QCOMPARE(s[1].radiusPx, 7.0);
    }

    void rimOnDrawnFrames_data()
    {
        QTest::addColumn<cv::Size>("size");
        QTest::addColumn<cv::Point2d>("centre");
        QTest::addColumn<double>("rim");
        QTest::newRow("640x480 centred, cut at top and bottom") << cv::Size(640, 480) << cv::Point2d(320, 240) << 246.0;
        QTest::newRow("640x480 off-centre") << cv::Size(640, 480) << cv::Point2d(301.6, 251.3) << 205.4;
        QTest::newRow("480x480 inside") << cv::Size(480, 480) << cv::Point2d(236.3, 243.7) << 222.2;
        QTest::newRow("505x480 off-centre, cut") << cv::Size(505, 480) << cv::Point2d(260.4, 229.2) << 238.9;
    }

    void rimOnDrawnFrames()
    {
        QFETCH(cv::Size, size);
        QFETCH(cv::Point2d, centre);
        QFETCH(double, rim);
        const auto frames = mirrorFrames(size, centre, rim, 47.0, 4);
        const RimFitResult result = fitRim(frames);
        QVERIFY2(result.ok(), result.ok() ? "" : result.error->message.c_str());
        const RimFit& f = result.fit;
        const QString got = QString("centre (%1, %2) rim %3 rms %4").arg(f.centre.x).arg(f.centre.y).arg(f.rimRadius).arg(f.rmsPx);
        // Issue 11 asks for 1 px; the sub-pixel edge gives ~0.03 px, so a quarter pixel keeps
        // a whole-pixel edge location from passing.
        QVERIFY2(std::hypot(f.centre.x - centre.x, f.centre.y - centre.y) < 0.25, qPrintable(got));
        QVERIFY2(std::abs(f.rimRadius - rim) < 0.25, qPrintable(got));
        QCOMPARE(f.outerRadius, f.rimRadius - RimFitOptions{}.marginPx);
        QVERIFY(f.inliers < int(f.points.size()));  // the obstacle's rays were dropped
        // One frame is enough for the rim.
        QVERIFY(fitRim({frames.front()}).ok());

        const BodyFitResult body = fitBody(frames, f.centre, f.rimRadius);
        QVERIFY2(body.ok(), body.ok() ? "" : body.error->message.c_str());
        QVERIFY2(std::abs(body.fit.bodyRadius - 47.0) < 1.0, qPrintable(QString("body %1").arg(body.fit.bodyRadius)));
        QCOMPARE(body.fit.innerRadius, body.fit.bodyRadius + BodyFitOptions{}.marginPx);
    }

    // The scene simulator's cameras: off-centre mirrors, three frame sizes, dim light with
    // vignetting (the thin grey mirror ring then looks brighter than the carpet beside it),
    // other robots at the rim. The simulator draws the mirror's edge 6 px beyond outer_radius
    // and the robot body 2 px inside inner_radius.
    void rimOnSimulatedCameras_data()
    {
        QTest::addColumn<cv::Size>("size");
        QTest::addColumn<cv::Point2d>("centre");
        QTest::addColumn<double>("outer");
        QTest::addColumn<double>("inner");
        QTest::addColumn<double>("light");
        QTest::newRow("480x480 dim, vignetting") << cv::Size(480, 480) << cv::Point2d(236.7, 231.4) << 220.0 << 42.0 << 0.45;
        QTest::newRow("505x480 normal") << cv::Size(505, 480) << cv::Point2d(250.2, 242.6) << 225.0 << 55.0 << 1.0;
        QTest::newRow("640x480 bright, cut") << cv::Size(640, 480) << cv::Point2d(331.5, 236.2) << 250.0 << 48.0 << 1.3;
    }

    void rimOnSimulatedCameras()
    {
        QFETCH(cv::Size, size);
        QFETCH(cv::Point2d, centre);
        QFETCH(double, outer);
        QFETCH(double, inner);
        QFETCH(double, light);
        Config config;
        config.geometry.imageWidth = size.width;
        config.geometry.imageHeight = size.height;
        config.geometry.centerX = centre.x;
        config.geometry.centerY = centre.y;
        config.geometry.outerRadius = outer;
        config.geometry.innerRadius = inner;
        const SceneSimulator sim(config);
        std::vector<cv::Mat> frames;
        for (int i = 0; i < 6; ++i) {
            SceneOptions scene;
            scene.robot = {-2.0 + 0.7 * i, -1.0 + 0.3 * i, 0.4 + 0.5 * i};  // drives and turns
            scene.obstacles = {{scene.robot.x + 1.5, scene.robot.y + 2.5}};
            scene.lightLevel = light;
            scene.lightGradient = light < 1 ? 1.0 : 0.0;
            scene.noiseSigma = 3.0;
            scene.seed = 20u + unsigned(i);
            frames.push_back(sim.render(scene));
        }
        const RimFitResult rim = fitRim(frames);
        QVERIFY2(rim.ok(), rim.ok() ? "" : rim.error->message.c_str());
        const QString got = QString("centre (%1, %2) rim %3 outer %4").arg(rim.fit.centre.x).arg(rim.fit.centre.y).arg(rim.fit.rimRadius).arg(rim.fit.outerRadius);
        QVERIFY2(std::hypot(rim.fit.centre.x - centre.x, rim.fit.centre.y - centre.y) < 0.5, qPrintable(got));
        // Inside the mirror image, and not much inside the ring the config was drawn with (bounds
        // set when the margin was 4 px; RimFitOptions::marginPx is 2 since 2026-12-01).
        const double widened = 4.0 - RimFitOptions{}.marginPx;
        QVERIFY2(rim.fit.outerRadius > outer - 1 && rim.fit.outerRadius < outer + 6 + widened, qPrintable(got));
        QVERIFY2(rim.fit.outerRadius < rim.fit.rimRadius, qPrintable(got));
        const BodyFitResult body = fitBody(frames, rim.fit.centre, rim.fit.rimRadius);
        QVERIFY2(body.ok(), body.ok() ? "" : body.error->message.c_str());
        QVERIFY2(std::abs(body.fit.innerRadius - inner) < 2.0, qPrintable(QString("inner %1").arg(body.fit.innerRadius)));
    }

    void rimRefusesFramesWithoutRim()
    {
        const std::vector<cv::Mat> black = {cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(0))};
        const RimFitResult a = fitRim(black);
        QVERIFY(!a.ok());
        QCOMPARE(int(a.error->kind), int(FitErrorKind::Uniform));
        QVERIFY(a.error->message.find("no contrast") != std::string::npos);

        // The mirror overfills the frame: no dark outside anywhere.
        const RimFitResult b = fitRim({drawMirrorFrame({320, 240}, {160, 120}, 400, 30, 0, 1)});
        QVERIFY(!b.ok());
        QCOMPARE(int(b.error->kind), int(FitErrorKind::NoRim));
        QVERIFY2(b.error->message.find("dark outside") != std::string::npos, b.error->message.c_str());

        const RimFitResult c = fitRim({});
        QCOMPARE(int(c.error->kind), int(FitErrorKind::BadInput));
        const RimFitResult d = fitRim({cv::Mat(480, 640, CV_8UC3), cv::Mat(480, 480, CV_8UC3)});
        QCOMPARE(int(d.error->kind), int(FitErrorKind::BadInput));
        QVERIFY(d.error->message.find("480x480") != std::string::npos);
    }

    void progressAndCancel()
    {
        const auto frames = mirrorFrames({480, 480}, {240, 240}, 220, 45, 3);
        RecordingProgress whole;
        QVERIFY(fitRim(frames, {}, &whole).ok());
        QCOMPARE(whole.last, 100.0);
        RecordingProgress body;
        QVERIFY(fitBody(frames, {240, 240}, 220, {}, &body).ok());
        QCOMPARE(body.last, 100.0);
        RecordingProgress stop(10);
        const RimFitResult a = fitRim(frames, {}, &stop);
        QVERIFY(!a.ok());
        QCOMPARE(int(a.error->kind), int(FitErrorKind::Cancelled));
        RecordingProgress stopBody(10);
        QCOMPARE(int(fitBody(frames, {240, 240}, 220, {}, &stopBody).error->kind), int(FitErrorKind::Cancelled));
    }

    void bodyRefusesTooFewOrStillFrames()
    {
        const cv::Mat frame = drawMirrorFrame({480, 480}, {240, 240}, 220, 45, 0, 3);
        const BodyFitResult one = fitBody({frame, frame}, {240, 240}, 220);
        QVERIFY(!one.ok());
        QCOMPARE(int(one.error->kind), int(FitErrorKind::TooFewFrames));
        QVERIFY(one.error->message.find("turns or drives") != std::string::npos);
        // The same view three times (noise differs only): the field did not move.
        const std::vector<cv::Mat> still = {frame, drawMirrorFrame({480, 480}, {240, 240}, 220, 45, 0, 4),
                                            drawMirrorFrame({480, 480}, {240, 240}, 220, 45, 0, 5)};
        const BodyFitResult s = fitBody(still, {240, 240}, 220);
        QVERIFY(!s.ok());
        QCOMPARE(int(s.error->kind), int(FitErrorKind::StaticField));
    }

    // The demo was rendered with config.yml: centre (320, 240), mirror edge 6 px beyond
    // outer_radius 240 (the simulator's rim margin), body 2 px inside inner_radius 50; its
    // truth radii come from the config's ball model. Tolerances: centre 1 px, radii 3 px, ball
    // radius 0.3 px over the marked span.
    void demoSessionGeometryAndBall()
    {
        SessionOpen opened = SessionReader::open(kDemo);
        QVERIFY(opened.ok());
        const ConfigLoad config = loadConfig(kDemo + "/config.yml");
        QVERIFY(config.ok());
        std::vector<cv::Mat> frames;
        for (int i = 0; i < opened.reader->frameCount(); i += 3) {
            cv::Mat f;
            QVERIFY(!opened.reader->readFrame(i, f));
            frames.push_back(f);
        }
        const RimFitResult rim = fitRim(frames);
        QVERIFY2(rim.ok(), rim.ok() ? "" : rim.error->message.c_str());
        const auto& g = config.config.geometry;
        const QString got = QString("centre (%1, %2) rim %3 outer %4").arg(rim.fit.centre.x).arg(rim.fit.centre.y).arg(rim.fit.rimRadius).arg(rim.fit.outerRadius);
        QVERIFY2(std::hypot(rim.fit.centre.x - g.centerX, rim.fit.centre.y - g.centerY) < 1.0, qPrintable(got));
        // The demo config's outer radius was set ~6 px inside the rim; the bound dates from the 4 px margin.
        QVERIFY2(std::abs(rim.fit.outerRadius - (4.0 - RimFitOptions{}.marginPx) - g.outerRadius) < 3.0, qPrintable(got));
        const BodyFitResult body = fitBody(frames, rim.fit.centre, rim.fit.rimRadius);
        QVERIFY2(body.ok(), body.ok() ? "" : body.error->message.c_str());
        QVERIFY2(std::abs(body.fit.innerRadius - g.innerRadius) < 3.0, qPrintable(QString("inner %1").arg(body.fit.innerRadius)));

        const auto samples = ballSamplesFromTruth(opened.reader->truth(), rim.fit.centre);
        const BallModelFitResult ball = fitBallModel(samples);
        QVERIFY2(ball.ok(), ball.ok() ? "" : ball.error->message.c_str());
        const BallModel model(config.config.ball);
        for (double d = ball.fit.minDistancePx; d <= ball.fit.maxDistancePx; d += 5)
            QVERIFY2(std::abs(ball.fit.radiusAt(d) - model.radiusAt(d)) < 0.3,
                     qPrintable(QString("at %1 px: %2 vs %3").arg(d).arg(ball.fit.radiusAt(d)).arg(model.radiusAt(d))));
    }
};

QTEST_GUILESS_MAIN(CalibFitTest)
#include "calib_fit_test.moc"
