#pragma once
// The detector: one call per frame, from the camera image to the ball in metres (thesis
// ch. 4). Holds every buffer between frames, so a warm pipeline allocates nothing on the
// specific path (cv::HoughCircles allocates inside OpenCV on the opencv/combined paths).
#include "core/Config.h"
#include "core/PipelineResult.h"

#include <memory>
#include <string>

namespace omnitune {

class Pipeline {
public:
    // Throws std::invalid_argument naming the key when the config is not usable.
    explicit Pipeline(const Config& config);
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    // Rebuilds the tables that depend on the config (LUT, geometry, Hough offsets).
    void setConfig(const Config& config);
    const Config& config() const;

    // Processes one frame into `result` (reuse the same result object between calls).
    // A frame of the wrong size or type sets result.error and leaves the rest empty.
    void process(const cv::Mat& frame, PixelFormat format, PipelineResult& result, bool wantStageImages = false);

    // Whether validation also scores what it rejects without needing to: OpenCV circles refused
    // before validation (centre outside the processed area, implausible radius), and the shape
    // of a candidate that failed a colour test (for the window's tooltips and the evaluation's
    // miss lists). Off, as on the robot, such candidates keep only what was measured before they
    // failed (ValidationScores::squareMeasured / shapeMeasured): the busiest optics-matrix frames
    // do 2-13 % less work, the verdicts are the same. The candidate prefilter's listed refusals
    // (hough.prefilter_*) are never validated either way.
    void setExplainRejections(bool on);

    // Whether the candidate prefilter lists every refusal (SpecificHough::setListEveryRefusal),
    // after the strongest few it always lists: the evaluation's miss diagnosis then tells a ball
    // refused past that cap from one no search found. The extra rows come after the specific
    // search's, are never judged again and change no verdict. Off, as on the robot and in the
    // window, whose panes would drown in them.
    void setListEveryRefusal(bool on);

    // Forgets running statistics (none today); here so every stage has the same shape.
    void reset();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace omnitune
