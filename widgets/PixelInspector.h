#pragma once
// The status-bar line for the pixel under the cursor: image x/y, BGR, HSV, colour class,
// distance to the robot centre in px and metres, and whether the pixel is processed.
#include "widgets/PipelineRunner.h"

#include <QString>

namespace omnitune {

QString describePixel(const PipelineRun& run, const Config& config, QPointF imagePos);

}  // namespace omnitune
