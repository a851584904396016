#pragma once
// Recording a simulated robot tour (Tour.h) as a session folder: every frame rendered by the
// SceneSimulator with its ground truth as a truth.csv row, and the config the frames were
// rendered with saved as the session's config.yml. omnitune-sim is this plus its arguments.
#include "calib/session/SessionIssue.h"
#include "calib/session/SessionWriter.h"
#include "calib/sim/Tour.h"

#include "core/Config.h"
#include "core/Progress.h"

#include <optional>
#include <string>

namespace omnitune {

struct TourRecordingOptions {
    TourOptions tour;
    bool ballPresent = true;     // false: the ball is left out (a session for false positives)
    double motionBlurPx = 0.0;   // blur length along the ball's image direction, px, >= 0
    double occlusion = 0.0;      // share of the ball hidden behind a robot edge, 0..0.9
    SessionWriterOptions writer;  // overwrite, PNG compression
};

// "omnitune-sim: ball orange, 300 frames, seed 1, head shadow": session.yml's notes.
std::string tourNotes(const TourRecordingOptions& options);

struct TourRecordingResult {
    int frames = 0;                     // frames written
    bool cancelled = false;             // stopped by `progress`; the session is closed with what was written
    std::optional<SessionIssue> error;  // the file and the fault; frames written before it stay readable

    bool ok() const { return !error.has_value(); }
};

// Renders the tour with `config`'s camera and writes it to `folder`. `progress` (may be null)
// sees the share of frames written and may cancel between frames.
TourRecordingResult recordTour(const std::string& folder, const Config& config, const TourRecordingOptions& options,
                               Progress* progress = nullptr);

}  // namespace omnitune
