// validation.recentre_refused (core/RefusalRecentre.h) on the optics simulator's green-and-white
// ball cells: the Hough maximum of that ball lies on its white half, where the square is mostly
// carpet by class; moved to the centroid of what is not the carpet's colour and validated there,
// more of those balls are found, and no ball-free frame gains a detection.
#include "VariantGain.h"

#include "calib/sim/optics/OpticsCell.h"
#include "core/Pipeline.h"

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

    // A recentred refusal that passed is a validated candidate: it moves before the refusals
    // still listed (hough.prefilterListed counts only those, at the end of the specific
    // search's rows), which is what the window's table relies on to show their shape as unmeasured.
    void keptRecentresPrecedeTheListedRefusals()
    {
        QualityMatrixOptions matrix;
        matrix.framesPerCell = 2;
        matrix.ballFreeCells = false;
        int kept = 0;
        for (const OpticsCell& cell : filterOpticsCells(qualityMatrixCells(matrix), "green-white/normal")) {
            OpticsCellFrames rendered = renderCell(cell);
            rendered.fittedConfig.algorithm = Algorithm::Specific;
            Pipeline pipeline(rendered.fittedConfig);
            PipelineResult r;
            for (const cv::Mat& frame : rendered.frames) {
                pipeline.process(frame, PixelFormat::Bgr8, r);
                QVERIFY(r.hough.recentred <= r.hough.recentreTried);
                const std::size_t tail =
                    r.candidates.size() - std::size_t(r.hough.prefilterListed + r.hough.prefilterUnlisted);
                for (std::size_t i = tail; i < r.candidates.size(); ++i) {
                    const RejectReason why = r.candidates[i].rejected;
                    QVERIFY(why != RejectReason::None && why != RejectReason::NotChosen);
                }
                for (std::size_t i = tail - std::size_t(r.hough.recentred); i < tail; ++i) {
                    const RejectReason why = r.candidates[i].rejected;
                    QVERIFY(why == RejectReason::None || why == RejectReason::NotChosen);
                }
                kept += r.hough.recentred;
            }
        }
        qInfo("recentred refusals kept: %d", kept);
        QVERIFY(kept >= 1);
    }
};

QTEST_GUILESS_MAIN(EvalRecentreTest)
#include "calib_eval_recentre_test.moc"
