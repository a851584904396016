// omnitune-eval --false-positives (issue 9): every false-positive frame of a quality run is
// listed with what was detected, and its surroundings written as a PNG to look at. On the
// optics simulator's ball-free 480x480 cell where two far lines meet at the horizon, the
// junction is a false positive with validation.line_arms off and none with it on.
#include "calib/eval/FalsePositiveList.h"
#include "calib/eval/QualityMatrix.h"
#include "calib/eval/QualityRun.h"
#include "PlainFile.h"

#include <opencv2/imgcodecs.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace omnitune;

namespace {

// A ball-free cell with a line junction at the horizon (found by omnitune-eval --false-positives).
const char* const kJunctionCell = "orange,bright,none,480x480,dark-green,spherical,no-ball";

std::vector<OpticsCell> junctionCell()
{
    QualityMatrixOptions matrix;
    matrix.framesPerCell = 2;
    std::vector<OpticsCell> cells = filterOpticsCells(qualityMatrixCells(matrix), kJunctionCell);
    return cells;
}

QualityRun runJunction()
{
    QualityVariant off{"combined, validation.line_arms=false", Algorithm::Combined, {{"validation.line_arms", "false", ""}}};
    QualityVariant on{"combined", Algorithm::Combined, {}};
    return runQuality(junctionCell(), {off, on});
}

}  // namespace

class EvalFpListTest : public QObject {
    Q_OBJECT
private slots:
    void junctionIsListedAndWritten()
    {
        QCOMPARE(junctionCell().size(), std::size_t(1));
        const QualityRun run = runJunction();
        QCOMPARE(run.cells.size(), std::size_t(1));
        const QualityTally& off = run.cells[0].tallies[0];
        const QualityTally& on = run.cells[0].tallies[1];
        // Every counted false positive has its record, and line_arms is what removes this one.
        QCOMPARE(int(off.falsePositiveFrames.size()), off.falsePositives);
        QVERIFY2(off.falsePositives >= 1, "the junction cell has no false positive with line_arms off");
        QCOMPARE(on.falsePositives, 0);
        QVERIFY(on.falsePositiveFrames.empty());

        const FalsePositiveFrame& fp = off.falsePositiveFrames.front();
        QVERIFY(!fp.ballVisible);
        QVERIFY(!fp.crop.image.empty());
        QVERIFY(fp.chosen.expectedRadiusPx > 0.0);

        const std::string md = falsePositiveListMarkdown(run, {0, 1});
        qInfo().noquote() << QString::fromStdString(md);
        QVERIFY(md.find(run.cells[0].name) != std::string::npos);
        const std::string at = "(" + std::to_string(fp.chosen.x) + ", " + std::to_string(fp.chosen.y) + ")";
        QVERIFY2(md.find(at) != std::string::npos, at.c_str());
        QVERIFY(md.find("| combined |") == std::string::npos);  // the variant with none lists no row

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string folder = (std::filesystem::path(dir.path().toStdString()) / "crops").string();
        const auto error = writeFalsePositiveCrops(run, {0, 1}, folder, 4);
        QVERIFY2(!error, error ? error->c_str() : "");
        int files = 0;
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            const cv::Mat png = cv::imread(entry.path().string());
            QCOMPARE(png.cols, fp.crop.image.cols * 4);
            QCOMPARE(png.rows, fp.crop.image.rows * 4);
            ++files;
        }
        QCOMPARE(files, off.falsePositives);
    }

    void noFalsePositiveSaysNone()
    {
        QualityRun run;
        run.variants = {{"combined", Algorithm::Combined, {}}};
        run.cells.push_back({});
        run.cells.back().tallies.resize(1);
        QVERIFY(falsePositiveListMarkdown(run, {0}).find("(none)") != std::string::npos);
    }

    void unwritableFolderIsNamed()
    {
        QTemporaryDir dir;
        const std::string file = makePlainFile(dir);
        QVERIFY(!file.empty());
        const auto error = writeFalsePositiveCrops(QualityRun{}, {}, file + "/sub");
        QVERIFY(error);
        QVERIFY2(error->find(file) != std::string::npos, error->c_str());
    }
};

QTEST_GUILESS_MAIN(EvalFpListTest)
#include "calib_eval_fp_list_test.moc"
