#pragma once
// A first geometry for frames of another size than the config's (issue 11: "a new camera opens
// and shows its frames at once"). Without it every pane of a new camera stays empty until a
// config for its size is written by hand. The guess: the mirror is the largest circle inscribed
// in the frame, centred on it; every radius-like value of the old config (inner radius, radial
// areas, sensors, distance map, ball model) is scaled by the ratio of the two outer radii, so
// the detector runs and the user can fit the real centre and rim from there.
#include "core/Config.h"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace omnitune {

struct ProvisionalGeometry {
    Config config;                     // `from`, adapted to the frame size
    double scale = 1.0;                // new outer radius / old outer radius
    std::vector<std::string> changes;  // one line per part changed, for the user ("mask dropped: ...")
};

// `frameSize` must be positive. The mask (of the old size) is dropped and mask_file cleared.
ProvisionalGeometry provisionalGeometry(const Config& from, cv::Size frameSize);

}  // namespace omnitune
