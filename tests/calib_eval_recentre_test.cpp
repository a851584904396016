// validation.recentre_refused (core/RefusalRecentre.h) on the optics simulator's green-and-white
// ball cells: the Hough maximum of that ball lies on its white half, where the square is mostly
// carpet by class; moved to the centroid of what is not the carpet's colour and validated there,
// more of those balls are found, and no ball-free frame gains a detection.
#include "VariantGain.h"

using namespace omnitune;

class EvalRecentreTest : public QObject {
    Q_OBJECT
private slots:
    void moreGreenAndWhiteBallsAreFound()
    {
        const QualityVariant off{"specific, no recentre", Algorithm::Specific, {{"validation.recentre_refused", "0", ""}}};
        const VariantGain g = runVariantGain("green-white", true, off, {"specific", Algorithm::Specific, {}});
        QVERIFY(g.after.withBall >= 60);
        QVERIFY(g.after.correct >= g.before.correct + 4);
        QVERIFY(g.after.falsePositives <= g.before.falsePositives);
    }
};

QTEST_GUILESS_MAIN(EvalRecentreTest)
#include "calib_eval_recentre_test.moc"
