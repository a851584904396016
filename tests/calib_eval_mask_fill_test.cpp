// opencv_hough.mask_fill_px and opencv_hough.masked_centres on the optics simulator's rods cells,
// where the ball lies beside or behind a masked support rod: the OpenCV search finds more of
// those balls with them than with the thesis' input (masked pixels green, centres on them refused).
#include "VariantGain.h"

using namespace omnitune;

class EvalMaskFillTest : public QObject {
    Q_OBJECT
private slots:
    void openCvFindsMoreBallsBesideRods()
    {
        const QualityVariant thesis{"opencv, thesis input", Algorithm::OpenCv,
                                    {{"opencv_hough.mask_fill_px", "0", ""}, {"opencv_hough.masked_centres", "false", ""}}};
        const VariantGain g = runVariantGain("rods", false, thesis, {"opencv", Algorithm::OpenCv, {}});
        QVERIFY(g.after.withBall >= 100);
        QVERIFY(g.after.correct >= g.before.correct + 6);
        QVERIFY(g.after.falsePositives <= g.before.falsePositives);
    }
};

QTEST_GUILESS_MAIN(EvalMaskFillTest)
#include "calib_eval_mask_fill_test.moc"
