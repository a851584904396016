#pragma once
// A light blur of the camera frame before segmentation, only when the frame is noisy (issue 9;
// not in the thesis, which segments the frame as acquired). Sensor noise in dim halls or at
// high gain turns single pixels of the carpet into other classes and breaks a small ball's
// outline into specks; a 3x3 Gaussian evens both out, and on clean frames costs the far balls
// their last pixels of contrast, so it runs only above a measured noise level (core/FrameNoise.h).
// Optics matrix, seeds 1-8, combined: 5589 -> 5648 balls, false-positive frames 32 -> 30
// (docs/evaluation.md, 2026-12-07 thirty-third session). A UYVY frame (the thesis' IIDC camera)
// has only its colour blurred: read as UYVY, 5591 / 52 -> 5609 / 51 (thirty-fourth session).
#include "core/PixelFormat.h"

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace omnitune {

struct RowSpan;

struct DenoiseOptions {
    // Levels; a frame whose noise sigma (core/FrameNoise.h) is above this is blurred before
    // segmentation. 0: never (the thesis).
    double aboveNoise = 4.0;
    double blurSigma = 0.8;  // px; the 3x3 Gaussian's sigma
};

class FrameDenoiser {
public:
    explicit FrameDenoiser(const DenoiseOptions& options);

    // `frame` itself, or its blurred copy (valid until the next call) when the frame's noise over
    // `spans` is above options.aboveNoise, in the frame's own format: BGR's three channels; UYVY's
    // U and V only (the same sigma in pixels, so fewer of their half-resolution samples), its Y
    // as captured. A warm denoiser allocates nothing.
    const cv::Mat& apply(const cv::Mat& frame, PixelFormat format, const std::vector<RowSpan>& spans);

    double lastNoise() const { return lastNoise_; }  // levels; 0 when not measured
    bool lastBlurred() const { return lastBlurred_; }

private:
    void blur(const cv::Mat& frame, PixelFormat format);

    DenoiseOptions options_;
    int side_ = 0;    // the kernel's outer weight, of 256 (the centre has 256 - 2 x side_)
    int chromaSide_ = 0;  // the same for UYVY's U and V along a row (their samples are 2 px apart)
    cv::Mat blurred_;
    std::vector<std::uint16_t> rows_;  // horizontal pass, three rows (x 256; UYVY: its U and V)
    double lastNoise_ = 0.0;
    bool lastBlurred_ = false;
};

}  // namespace omnitune
