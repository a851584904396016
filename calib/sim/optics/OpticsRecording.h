#pragma once
// A session folder from one optics cell (omnitune-sim --optics): its frames with truth.csv, the
// config FITTED from the camera's measurements as config.yml (never the simulator's truth), the
// measurements themselves under measurements/ (CameraMeasurements.h, plus ball_samples.csv for
// `omnitune-calibrate ball-model --samples`), and notes naming the conditions.
#include "calib/session/SessionWriter.h"
#include "calib/sim/optics/OpticsCell.h"
#include "core/Progress.h"

#include <optional>
#include <string>

namespace omnitune {

struct OpticsRecordingResult {
    int frames = 0;
    int visibleBalls = 0;
    bool cancelled = false;
    std::optional<std::string> error;

    bool ok() const { return !error.has_value(); }
};

// "optics simulator: ball orange, light normal, ..." (several lines).
std::string opticsCellNotes(const OpticsCell& cell, const MeasuredCalibration& calibration);

OpticsRecordingResult recordOpticsSession(const std::string& folder, const OpticsCell& cell, const Config& base,
                                          const SessionWriterOptions& writer = {}, Progress* progress = nullptr);

}  // namespace omnitune
