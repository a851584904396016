#pragma once
// The segmented pane as the colour editor shows it: "show only this class" dims every other
// pixel, and the pixels two or more classes claim are flagged with red and white stripes (no
// class's display colour looks like that), so a box that reaches into another class shows.
#include <opencv2/core.hpp>

namespace omnitune {

struct ClassViewOptions {
    int onlyClass = -1;  // class id (1..N) to show alone; -1: every class
    bool flagOverlaps = false;
};

// `segmented`: the segmented stage image (BGR false colours); `classes`: its class ids
// (CV_8UC1); `overlap`: CV_8UC1, non-zero where two or more classes claim the pixel (may be
// empty). Returns a new BGR image.
cv::Mat classView(const cv::Mat& segmented, const cv::Mat& classes, const cv::Mat& overlap,
                  const ClassViewOptions& options);

}  // namespace omnitune
