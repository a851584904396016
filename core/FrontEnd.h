#pragma once
// The detector's front end (thesis ch. 4, Fig. 4.6): camera frame -> colour classes -> binary
// image (green and unprocessed pixels white; white lines at edges.white_level) -> Canny edges
// inside the processed ring. With edges.input: gray, Canny runs on the frame's grayscale
// instead (thesis solutions 2 and 4); the classes and the binary image are still made, for
// validation and for the Hough's "centre is not green" test. The
// pipeline, the core tests and the bench all run this one path, so what they test and time is
// what the robot runs.
#include "core/ColorLut.h"
#include "core/Config.h"
#include "core/Edges.h"
#include "core/Geometry.h"
#include "core/PipelineResult.h"
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

namespace omnitune {

class FrontEnd {
public:
    // Compiles the colour table and the geometry (ring, mask, edge mask) of `config`.
    explicit FrontEnd(const Config& config);

    const Geometry& geometry() const { return geometry_; }
    const ColorLut& lut() const { return lut_; }
    // What each class id of `classes` is used for (config.colors.classes' roles).
    const ColourRoles& roles() const { return roles_; }
    const EdgeOptions& edgeOptions() const { return edgeOptions_; }
    // The carpet brightness and black threshold of the last frame (relative black only).
    const SegmentStats& segmentStats() const { return stats_; }

    // The image Canny ran on in the last process(): `binary` itself, or the frame's grayscale
    // with edges.input: gray. The grayscale pane shows it; cv::HoughCircles (which runs its own
    // Canny) takes it.
    const cv::Mat& edgeSource(const cv::Mat& binary) const
    {
        return edgeOptions_.input == EdgeInput::Gray ? gray_ : binary;
    }

    // `frame` must have the geometry's size and the format's type (Pipeline reports a frame
    // that does not as an error before calling this). Fills `classes` (class ids, Unknown
    // outside the ring), `binary` and `edges`; the outputs and the Canny scratch buffers are
    // reused, so a warm front end allocates nothing. `timings`, when given, gets the segment,
    // binary and edge stage times.
    void process(const cv::Mat& frame, PixelFormat format, cv::Mat& classes, cv::Mat& binary, cv::Mat& edges,
                 StageTimings* timings = nullptr);

private:
    ColorLut lut_;
    ColourRoles roles_;
    Geometry geometry_;
    EdgeOptions edgeOptions_;
    EdgeOptions cannyOptions_;  // edgeOptions_ with drop_specks applied
    CannyDetector canny_;
    SegmentStats stats_;
    cv::Mat gray_;
};

}  // namespace omnitune
