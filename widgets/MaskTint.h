#pragma once
// The robot mask as the panes show it (issue 11): its unprocessed pixels tinted over every
// pane, so the user sees what the detector never looks at (body, rods) on any stage image,
// not only its outline. Built once per mask on the runner's thread, shared by the five panes.
#include <opencv2/core.hpp>

#include <QImage>

#include <memory>

namespace omnitune {

// Null for an empty mask. `mask`: CV_8UC1, 0 = not processed.
std::shared_ptr<const QImage> maskTint(const cv::Mat& mask);

}  // namespace omnitune
