#pragma once
// What one pipeline call produces.
#include "core/BallCandidate.h"
#include "core/SpecificHough.h"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace omnitune {

struct BallDetection {
    bool found = false;
    double px = 0.0;        // ball centre in the image, px
    double py = 0.0;
    double radiusPx = 0.0;
    double distancePx = 0.0; // from the robot centre
    double xM = 0.0;         // world position relative to the robot, m (x along image +x)
    double yM = 0.0;         // m (y along image -y, so that +y points "up" in the image)
    double distanceM = 0.0;  // horizontal distance, height-corrected
    int candidate = -1;      // index into PipelineResult::candidates
};

struct StageTimings {
    double segmentMs = 0.0;
    double binaryMs = 0.0;
    double edgesMs = 0.0;
    double houghMs = 0.0;       // specific and/or OpenCV Hough
    double validationMs = 0.0;
    double totalMs = 0.0;
};

// The five images of thesis Fig. 4.6 (+ the Hough accumulator), filled only when asked for.
struct StageImages {
    cv::Mat acquired;   // BGR
    cv::Mat segmented;  // BGR false colour of the classes
    cv::Mat grayscale;  // what Canny saw: binary (green/unprocessed 255, white edges.white_level, other 0) or the gray frame
    cv::Mat edges;      // 0/255
    cv::Mat hough;      // BGR heat map of the 3x3 vote sums
};

struct PipelineResult {
    std::string error;  // non-empty when the frame could not be processed
    BallDetection detection;
    std::vector<BallCandidate> candidates;
    StageTimings timings;
    HoughStats hough;   // edge pixels voting (subsampled beyond hough.max_edge_pixels), maxima, seeds
    double frameNoise = 0.0;  // the frame's noise sigma, levels (0: not measured: denoise.above_noise 0)
    bool denoised = false;    // the frame was blurred before segmentation (denoise.above_noise)
    bool opencvSkipped = false;  // combined: the OpenCV search was due but skipped (opencv_hough.max_edge_pixels)
    StageImages stages;
    cv::Mat classes;    // CV_8UC1 colour class ids (always filled)

    bool ok() const { return error.empty(); }
};

}  // namespace omnitune
