#pragma once
// The CSV omnitune-detect writes: one row per frame, the detection and the scores of the
// candidate that decided it (the chosen ball, else the candidate that came closest).
#include "core/PipelineResult.h"

#include <string>

namespace omnitune {

// frame,found,px,py,radius_px,x_m,y_m,time_ms,candidates,non_green_pct,non_black_pct,
// circularity_pct,source,rejected,error
std::string detectionCsvHeader();
std::string detectionCsvRow(int frame, const PipelineResult& result);

// A CSV field, quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text);

}  // namespace omnitune
