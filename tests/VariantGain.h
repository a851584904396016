#pragma once
// Two variants of the detector on the same optics cells, totalled: what a switch buys where it is
// meant to (the eval tests of opencv_hough.mask_fill_px and validation.recentre_refused).
#include "calib/eval/QualityMatrix.h"
#include "calib/eval/QualityRun.h"

#include <QtTest>

#include <string>
#include <vector>

struct VariantGain {
    omnitune::QualityTally before;  // the first variant (the switch off)
    omnitune::QualityTally after;   // the second (as configured)
};

// The cells of a 2-frames-per-cell matrix whose names hold `parts` (with or without the
// ball-free ones), run with `off` and `on`; logs what each found.
inline VariantGain runVariantGain(const std::string& parts, bool ballFreeCells, const omnitune::QualityVariant& off,
                                  const omnitune::QualityVariant& on)
{
    omnitune::QualityMatrixOptions matrix;
    matrix.framesPerCell = 2;
    matrix.ballFreeCells = ballFreeCells;
    const auto cells = omnitune::filterOpticsCells(omnitune::qualityMatrixCells(matrix), parts);
    const omnitune::QualityRun run = omnitune::runQuality(cells, {off, on});
    VariantGain g{omnitune::qualityTotal(run, 0), omnitune::qualityTotal(run, 1)};
    qInfo("%zu '%s' cells, %d balls: %s found %d, %s %d", cells.size(), parts.c_str(), g.after.withBall, off.name.c_str(),
          g.before.correct, on.name.c_str(), g.after.correct);
    return g;
}
