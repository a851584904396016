// omnitune-eval --miss-list (issue 9): every missed ball frame of a quality run is listed with
// its cause and the candidate at the ball, and its surroundings written as a PNG to look at. A
// variant that refuses every candidate as too small (validation.min_radius_px 100) misses every
// ball of an orange, normal-light cell, so the test does not depend on today's detector.
#include "calib/eval/MissList.h"
#include "calib/eval/QualityMatrix.h"
#include "calib/eval/QualityReport.h"
#include "calib/eval/QualityRun.h"
#include "PlainFile.h"

#include <opencv2/imgcodecs.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace omnitune;

namespace {

std::vector<OpticsCell> orangeCell()
{
    QualityMatrixOptions matrix;
    matrix.framesPerCell = 2;
    for (const OpticsCell& c : filterOpticsCells(qualityMatrixCells(matrix), "orange/normal/none/640x480"))
        if (c.ballPresent) return {c};
    return {};
}

const QualityVariant kRefuseAll{"combined, validation.min_radius_px=100", Algorithm::Combined,
                                {{"validation.min_radius_px", "100", ""}}};

QualityRun runOrange(bool recordMisses)
{
    QualityRunOptions options;
    options.recordMisses = recordMisses;
    return runQuality(orangeCell(), {kRefuseAll}, Config{}, options);
}

int countFiles(const std::string& folder)
{
    int n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) n += entry.is_regular_file();
    return n;
}

}  // namespace

class EvalMissListTest : public QObject {
    Q_OBJECT
private slots:
    void everyMissIsListedWithItsCause()
    {
        QCOMPARE(orangeCell().size(), std::size_t(1));
        const QualityRun run = runOrange(true);
        const QualityTally& t = run.cells.at(0).tallies.at(0);
        QVERIFY2(t.withBall == 2, "the orange cell should show its ball in both frames");
        QCOMPARE(t.correct, 0);
        // One record per miss, and the records' causes add up to the tally's.
        QCOMPARE(int(t.missedFrames.size()), t.withBall - t.correct);
        std::array<int, kMissCauseCount> causes{};
        for (const MissedFrame& m : t.missedFrames) {
            ++causes[std::size_t(m.cause)];
            QVERIFY(!m.crop.image.empty());
            QVERIFY(m.truthRadiusPx > 0.0);
            QVERIFY(m.truthRangeM > 0.3);
            if (m.hasCandidate) QVERIFY(std::hypot(m.atBall.x - m.truthPx, m.atBall.y - m.truthPy) <= std::max(m.truthRadiusPx, 2.0));
        }
        QVERIFY(causes == t.missCauses);
        const MissedFrame& m = t.missedFrames.front();
        QVERIFY2(m.cause == MissCause::TooSmall, std::string(missCauseName(m.cause)).c_str());

        const std::string md = missListMarkdown(run, {0});
        qInfo().noquote() << QString::fromStdString(md);
        QVERIFY(md.find(run.cells[0].name) != std::string::npos);
        QVERIFY(md.find("| too small |") != std::string::npos);
        const std::string at = "(" + std::to_string(m.atBall.x) + ", " + std::to_string(m.atBall.y) + ")";
        QVERIFY2(md.find(at) != std::string::npos, at.c_str());
        // Filtered by another cause, nothing is left.
        QVERIFY(missListMarkdown(run, {0}, MissCause::NonGreen).find("(none)") != std::string::npos);

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string folder = (std::filesystem::path(dir.path().toStdString()) / "misses").string();
        auto error = writeMissCrops(run, {0}, folder, std::nullopt, 4);
        QVERIFY2(!error, error ? error->c_str() : "");
        QCOMPARE(countFiles(folder), int(t.missedFrames.size()));
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            QVERIFY2(entry.path().filename().string().find("too-small") != std::string::npos, entry.path().c_str());
            const cv::Mat png = cv::imread(entry.path().string());
            QVERIFY(!png.empty());
            QCOMPARE(png.cols % 4, 0);  // enlarged 4 times
        }
        const std::string none = (std::filesystem::path(dir.path().toStdString()) / "none").string();
        error = writeMissCrops(run, {0}, none, MissCause::Circularity, 4);
        QVERIFY2(!error, error ? error->c_str() : "");
        QCOMPARE(countFiles(none), 0);
    }

    void aPrefilterRefusalAtTheBallIsMarked()
    {
        // A square twice the ball's diameter is mostly carpet: the candidate prefilter refuses every
        // maximum at the ball on its class share, and validation never sees one. The list says so,
        // as its scores are the prefilter's, not validation's.
        const QualityVariant wideSquare{"specific, ball.square_ratio=2", Algorithm::Specific,
                                        {{"ball.square_ratio", "2", ""}}};
        QualityRunOptions options;
        options.recordMisses = true;
        const QualityRun run = runQuality(orangeCell(), {wideSquare}, Config{}, options);
        const QualityTally& t = run.cells.at(0).tallies.at(0);
        QCOMPARE(t.correct, 0);
        int marked = 0;
        for (const MissedFrame& m : t.missedFrames) {
            if (!m.hasCandidate) continue;
            QVERIFY2(m.atBallPrefiltered, "the witness at the ball should be a prefilter refusal");
            QVERIFY2(m.cause == MissCause::NonGreen, std::string(missCauseName(m.cause)).c_str());
            ++marked;
        }
        QVERIFY2(marked > 0, "some miss should have a candidate at the ball");
        QCOMPARE(t.missesPrefiltered, marked);  // the tally counts them too
        const std::string md = missListMarkdown(run, {0});
        QVERIFY2(md.find("| non-green (prefilter) |") != std::string::npos, md.c_str());
        // The misses table's last column says how many of the misses the prefilter refused.
        const std::string table = qualityMissesMarkdown(run, 0);
        QVERIFY2(table.find("| by the prefilter |") != std::string::npos, table.c_str());
        const std::string allRow = "| all ball cells | " + std::to_string(t.withBall) + " |";
        const std::size_t row = table.find(allRow);
        QVERIFY2(row != std::string::npos, table.c_str());
        const std::string line = table.substr(row, table.find('\n', row) - row);
        const std::string last = " " + std::to_string(marked) + " |";
        QVERIFY2(line.size() > last.size() && line.compare(line.size() - last.size(), last.size(), last) == 0, line.c_str());

        // Validated candidates are not marked: the refuse-all variant's witnesses were validated
        // (their shape was measured) and refused as too small.
        const QualityRun validated = runOrange(true);
        for (const MissedFrame& m : validated.cells.at(0).tallies.at(0).missedFrames) {
            QVERIFY(m.hasCandidate);
            QVERIFY(m.atBall.scores.shapeMeasured);
            QVERIFY(!m.atBallPrefiltered);
        }
        QVERIFY(missListMarkdown(validated, {0}).find("(prefilter)") == std::string::npos);
        QCOMPARE(validated.cells.at(0).tallies.at(0).missesPrefiltered, 0);
    }

    void missesAreKeptOnlyWhenAsked()
    {
        const QualityRun run = runOrange(false);
        const QualityTally& t = run.cells.at(0).tallies.at(0);
        QVERIFY(t.withBall > t.correct);
        QVERIFY(t.missedFrames.empty());
    }

    void causesAreNamedAsTheTableNamesThem()
    {
        QVERIFY(missCauseNamed("non-green") == MissCause::NonGreen);
        QVERIFY(missCauseNamed("no candidate") == MissCause::NoCandidate);
        QVERIFY(missCauseNamed("no-candidate") == MissCause::NoCandidate);
        QVERIFY(missCauseNamed("out-of-area-radius") == MissCause::OutOfRange);
        QVERIFY(!missCauseNamed("bad luck"));
    }

    void unwritableFolderIsNamed()
    {
        QTemporaryDir dir;
        const std::string file = makePlainFile(dir);
        QVERIFY(!file.empty());
        const auto error = writeMissCrops(QualityRun{}, {}, file + "/sub");
        QVERIFY(error);
        QVERIFY2(error->find(file) != std::string::npos, error->c_str());
    }
};

QTEST_GUILESS_MAIN(EvalMissListTest)
#include "calib_eval_miss_list_test.moc"
