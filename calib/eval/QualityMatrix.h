#pragma once
// The quality gate's condition grid (issue 9, section 5): every ball kind x light x distractors
// at 640x480 and 480x480, plus ball-free cells that only count false positives. Few frames per
// cell, many cells: the grid's breadth, not its depth, is what a floor should hold.
#include "calib/sim/optics/OpticsCell.h"

#include <string>
#include <vector>

namespace omnitune {

struct QualityMatrixOptions {
    // Per ball cell. A frame costs ~20 ms to render and ~30 ms for the three algorithms: one
    // frame over 224 cells keeps the gate test in seconds (docs/evaluation.md uses 4).
    int framesPerCell = 1;
    int ballFreeFramesPerCell = 2;  // false positives are rare: more frames where nothing is there
    unsigned seed = 1;              // every cell gets its own seed derived from this one
    bool ballFreeCells = true;
    std::vector<cv::Size> sizes = {{640, 480}, {480, 480}};
    // Random: every frame its own ball direction (and rod). Spread reproduces the matrix before
    // 2026-12-02, whose one or two frames per cell saw the ball in two narrow sectors only.
    OpticsDirections directions = OpticsDirections::Random;
};

// The cells in a fixed order (size, light, distractors, ball; the ball-free cells last). The
// carpet cycles through its three greens across the grid so each colour meets every condition
// somewhere; 640x480 frames come through the hyperbolic mirror, 480x480 through the spherical
// one (the square sensors of the real teams in issue 9 sit behind such mirrors).
std::vector<OpticsCell> qualityMatrixCells(const QualityMatrixOptions& options = {});

// The cells whose opticsCellName holds every comma-separated part of `parts` ("dim,rods",
// "480x480"); all cells when `parts` is empty. For quick runs on a few conditions.
std::vector<OpticsCell> filterOpticsCells(const std::vector<OpticsCell>& cells, const std::string& parts);

}  // namespace omnitune
