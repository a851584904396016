#pragma once
// omnitune-eval --quality-matrix: the quality gate's matrix (calib/eval/QualityMatrix.h) run
// on the optics simulator and printed as markdown; --write-floors regenerates the gate's floors
// file, --floors checks a floors file as the test does, --deviations adds the runs with each
// deviation from the thesis switched off.
#include "app/CommandLine.h"

#include <vector>

namespace omnitune {

// The options this mode adds to omnitune-eval's.
std::vector<OptionSpec> qualityToolOptions();

// Runs the mode the parsed arguments ask for; the exit code (1 also when a --floors check fell).
int runQualityTool(const CommandLine& cl);

}  // namespace omnitune
