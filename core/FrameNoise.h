#pragma once
// How noisy a camera frame is: the standard deviation of its sensor noise, estimated from the
// frame alone (Immerkaer, "Fast noise variance estimation", 1996): the 3x3 difference of two
// Laplacians cancels flat areas and gentle gradients, so its mean magnitude over the image is
// proportional to the noise. Edges add a little; on the optics matrix the clean frames read
// 1.5-3 levels and the frames with sensor noise 5-6, a wide gap for a threshold.
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

struct RowSpan;

// Noise sigma (levels, 0..255) of the frame's green channel over `spans` (the processed ring),
// read on every fourth row (enough for a mean, and cheap). A UYVY frame's green is rebuilt per
// pixel as core's yuvToBgr does (unclipped), so one denoise.above_noise serves both formats.
// 0 when no pixel can be read.
double frameNoiseSigma(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans);

}  // namespace omnitune
