#pragma once
// The magic wand: from a clicked pixel, the 4-connected region of pixels whose colour is close
// to the clicked pixel's, inside the processed area. Each pixel is compared with the seed, not
// with its neighbour, so a slow gradient (vignetting) cannot lead the region off into another
// colour.
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

struct WandTolerance {
    int h = 8;   // hue steps (OpenCV's 0..179, on the circle) a pixel may differ from the seed
    int s = 50;  // saturation steps, 0..255
    int v = 50;  // value steps, 0..255
    // A seed less saturated than this has no reliable hue (white, grey, black): hue is ignored.
    int achromaticS = 30;
    // Region size limit in pixels (0: none); a tolerance that swallows the carpet stops here.
    int maxPixels = 0;
};

// `hsv`: the frame in OpenCV HSV (calib/colour/HsvImage.h); `used`: CV_8UC1, non-zero =
// processed (empty: every pixel). Empty result when the seed is outside the frame or not used.
std::vector<cv::Point> magicWand(const cv::Mat& hsv, const cv::Mat& used, cv::Point seed, const WandTolerance& tol);

}  // namespace omnitune
