#pragma once
// Canny thresholds that keep every border of the binary image and drop the rings around its
// one-pixel specks. On a two-level image the 3x3 Sobel's L1 gradient comes in multiples of the
// step: a straight border gives 4 steps, each pixel around an isolated speck 2 (beside it: 2 on one
// axis; diagonal to it: 1 on each). In dim light the black class freckles
// the carpet with such specks, and each speck's ring of edges votes like a tiny ball.
#include "core/Edges.h"
#include "core/OpenCvHough.h"

namespace omnitune {

// The smallest step between the binary image's levels (255, white_level rounded as makeBinary
// does, 0), in grey levels.
int binaryStep(int whiteLevel);

// The Canny options the front end uses: `options` as set, or with drop_specks on the binary
// input both thresholds raised to 4 x binaryStep - 1 (never lowered).
EdgeOptions speckFreeCannyOptions(const EdgeOptions& options);

// The same for cv::HoughCircles' internal Canny (its low threshold is half its high one): with
// opencv_hough.drop_specks on the binary input, canny_high raised to 4 x binaryStep - 1, so
// that the speckle's rings have no strong pixel and drop out while every border stays. A dim,
// noisy frame's speckle otherwise gives each ring's search hundreds of circle centres to
// estimate radii for (up to 30 ms a ring on the optics matrix's worst frame).
OpenCvHoughOptions speckFreeHoughOptions(const OpenCvHoughOptions& options, const EdgeOptions& edges);

}  // namespace omnitune
