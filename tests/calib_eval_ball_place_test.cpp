// Where a ball frame's ball lay (calib/eval/BallPlace.h): the quality report's range bands and
// "beyond the outer lines", and that a quality run counts every ball frame in exactly one band.
#include "calib/eval/BallPlace.h"
#include "calib/eval/QualityMatrix.h"
#include "calib/eval/QualityReport.h"
#include "calib/eval/QualityRun.h"
#include "calib/sim/FieldModel.h"

#include <QtTest>

#include <cmath>

using namespace omnitune;

namespace {

// A ball `rangeM` straight ahead of a robot at field (x, y) facing +x (robot forward = field +x).
TruthRow ballAhead(double robotX, double robotY, double rangeM)
{
    TruthRow t;
    t.ballVisible = true;
    t.xM = 0.0;
    t.yM = rangeM;
    t.robot = RobotPose{robotX, robotY, 0.0};
    return t;
}

bool in(const std::array<bool, kBallPlaceCount>& places, BallPlace p) { return places[std::size_t(p)]; }

}  // namespace

class EvalBallPlaceTest : public QObject {
    Q_OBJECT
private slots:
    void rangeBandsSplitAtTwoThreeAndFourMetres()
    {
        const FieldDimensions field;
        const double r = 0.11;
        QVERIFY(in(ballPlacesOf(ballAhead(0, 0, 1.99), field, r), BallPlace::Under2m));
        QVERIFY(in(ballPlacesOf(ballAhead(0, 0, 2.0), field, r), BallPlace::From2To3m));
        QVERIFY(in(ballPlacesOf(ballAhead(0, 0, 3.5), field, r), BallPlace::From3To4m));
        QVERIFY(in(ballPlacesOf(ballAhead(0, 0, 4.0), field, r), BallPlace::From4m));
        // One band each.
        for (double range : {0.5, 2.5, 3.9, 4.7}) {
            const auto places = ballPlacesOf(ballAhead(0, 0, range), field, r);
            int bands = 0;
            for (BallPlace p : {BallPlace::Under2m, BallPlace::From2To3m, BallPlace::From3To4m, BallPlace::From4m})
                bands += in(places, p);
            QCOMPARE(bands, 1);
        }
    }

    void outOfPlayOnlyWhenWhollyPastAnOuterLine()
    {
        const FieldDimensions field;  // 18 x 12 m between line centres
        const double r = 0.11;
        const double goalLineOuter = field.length / 2 + field.lineWidth / 2;
        // Straight ahead along +x from 5 m: the ball's centre at 5 + range.
        QVERIFY(!in(ballPlacesOf(ballAhead(5.0, 0.0, goalLineOuter - 5.0), field, r), BallPlace::OutOfPlay));  // on the line
        QVERIFY(!in(ballPlacesOf(ballAhead(5.0, 0.0, goalLineOuter + r - 0.01 - 5.0), field, r), BallPlace::OutOfPlay));
        QVERIFY(in(ballPlacesOf(ballAhead(5.0, 0.0, goalLineOuter + r + 0.01 - 5.0), field, r), BallPlace::OutOfPlay));
        // Beyond a touch line: the robot at y = 4 facing +y (heading 90 degrees).
        TruthRow t = ballAhead(0.0, 4.0, 3.0);
        t.robot->heading = M_PI / 2;
        QVERIFY(in(ballPlacesOf(t, field, r), BallPlace::OutOfPlay));  // y = 7: past 6.06
        t.yM = 1.5;                                                     // y = 5.5: in play
        QVERIFY(!in(ballPlacesOf(t, field, r), BallPlace::OutOfPlay));
        // Without the robot's pose the field position is unknown: never out of play.
        t.yM = 3.0;
        t.robot.reset();
        QVERIFY(!in(ballPlacesOf(t, field, r), BallPlace::OutOfPlay));
    }

    void aQualityRunCountsEachBallFrameInOneBand()
    {
        QualityMatrixOptions matrix;
        matrix.framesPerCell = 4;  // the frames' ranges spread 0.5-5 m: every band is met
        std::vector<OpticsCell> cells;
        for (const OpticsCell& c : filterOpticsCells(qualityMatrixCells(matrix), "orange/normal/none/640x480"))
            if (c.ballPresent) cells.push_back(c);
        QCOMPARE(cells.size(), std::size_t(1));
        const QualityRun run = runQuality(cells, {algorithmVariants().front()});
        const QualityTally t = qualityTotal(run, 0);
        QVERIFY(t.withBall >= 3);
        int withBall = 0, correct = 0, bands = 0;
        for (BallPlace p : {BallPlace::Under2m, BallPlace::From2To3m, BallPlace::From3To4m, BallPlace::From4m}) {
            const BallFrameTally& b = t.byPlace[std::size_t(p)];
            withBall += b.withBall;
            correct += b.correct;
            bands += b.withBall > 0;
        }
        QCOMPARE(withBall, t.withBall);
        QCOMPARE(correct, t.correct);
        QVERIFY2(bands >= 3, "four frames spread over 0.5-5 m should meet at least three bands");
        const std::string md = qualityBreakdownMarkdown(run, {0});
        QVERIFY2(md.find("| range: under 2 m | ") != std::string::npos, md.c_str());
        QVERIFY2(md.find("| range: 4 m and more | ") != std::string::npos, md.c_str());
    }
};

QTEST_GUILESS_MAIN(EvalBallPlaceTest)
#include "calib_eval_ball_place_test.moc"
