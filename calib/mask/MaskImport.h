#pragma once
// A mask image made elsewhere, turned into OmniTune's convention (CV_8UC1, 255 = process).
// Teams paint masks both ways round and in colours (red robot on black, white field on
// black): the user says which side means "process"; bright is any pixel whose largest channel
// is at least half way up, so a pure red counts as bright, as the eye sees it.
#include "calib/fit/FitError.h"
#include "core/Geometry.h"

#include <opencv2/core.hpp>

#include <optional>

namespace omnitune {

enum class MaskConvention {
    BrightProcesses,  // white (or any bright colour) = process, dark = robot: OmniTune's own
    DarkProcesses,    // black = process, bright = robot
};

struct MaskImport {
    cv::Mat mask;                 // CV_8UC1, 255 = process
    double processedShare = 0.0;  // share of the geometry's ring the mask lets through
};

struct MaskImportResult {
    MaskImport fit;  // meaningful only when ok()
    std::optional<FitError> error;

    bool ok() const { return !error.has_value(); }
};

// `image`: 8-bit grey, BGR or BGRA (alpha ignored) of the geometry's image size. Refused: another
// size, another pixel type, and an image that comes out all one value (it marks nothing).
MaskImportResult importMask(const cv::Mat& image, MaskConvention convention, const GeometryOptions& geometry);

}  // namespace omnitune
