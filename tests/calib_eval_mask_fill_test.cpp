// opencv_hough.mask_fill_px and opencv_hough.masked_centres on the optics simulator's rods cells,
// where the ball lies beside or behind a masked support rod: the OpenCV search finds more of
// those balls with them than with the thesis' input (masked pixels green, centres on them refused).
#include "calib/eval/QualityMatrix.h"
#include "calib/eval/QualityRun.h"

#include <QtTest>

using namespace omnitune;

class EvalMaskFillTest : public QObject {
    Q_OBJECT
private slots:
    void openCvFindsMoreBallsBesideRods()
    {
        QualityMatrixOptions matrix;
        matrix.framesPerCell = 2;
        matrix.ballFreeCells = false;
        const std::vector<OpticsCell> cells = filterOpticsCells(qualityMatrixCells(matrix), "rods");
        QVERIFY(cells.size() >= 50);
        const QualityVariant thesis{"opencv, thesis input", Algorithm::OpenCv,
                                    {{"opencv_hough.mask_fill_px", "0", ""}, {"opencv_hough.masked_centres", "false", ""}}};
        const QualityVariant ours{"opencv", Algorithm::OpenCv, {}};
        const QualityRun run = runQuality(cells, {thesis, ours});
        const QualityTally before = qualityTotal(run, 0);
        const QualityTally after = qualityTotal(run, 1);
        qInfo("OpenCV on %d rods-cell balls: %d found with the thesis' input, %d with the fill", after.withBall,
              before.correct, after.correct);
        QVERIFY(after.correct >= before.correct + 6);
        QVERIFY(after.falsePositives <= before.falsePositives);
    }
};

QTEST_GUILESS_MAIN(EvalMaskFillTest)
#include "calib_eval_mask_fill_test.moc"
