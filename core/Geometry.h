#pragma once
// Where the robot sits in the image and which pixels are worth processing: the robot centre,
// the ring between inner and outer radius, and a mask of pixels never processed (robot body,
// mirror support rods, reflections). Thesis ch. 4: mask image, `usedPixels`, distance table.
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace omnitune {

struct GeometryOptions {
    int imageWidth = 640;       // px; frames of another size are refused
    int imageHeight = 480;      // px
    double centerX = 320.0;     // robot centre in the image, px
    double centerY = 240.0;     // px
    double innerRadius = 50.0;  // px; pixels closer to the centre are the robot itself
    double outerRadius = 240.0; // px; pixels farther are outside the mirror
    std::string maskFile;       // mask image next to config.yml (white = process); empty: none
};

// One horizontal run of processed pixels: row y, columns [x0, x1).
struct RowSpan {
    int y = 0;
    int x0 = 0;
    int x1 = 0;
};

class Geometry {
public:
    Geometry() = default;
    // `mask` is optional (empty, or CV_8UC1 of the image size; non-zero = process).
    // `options` and `mask` must have passed checkConfig() (the one place user values are checked).
    Geometry(const GeometryOptions& options, const cv::Mat& mask);

    const GeometryOptions& options() const { return options_; }
    cv::Size imageSize() const { return {options_.imageWidth, options_.imageHeight}; }
    // 255 where a pixel is processed, 0 elsewhere.
    const cv::Mat& usedMask() const { return used_; }
    // 255 where an edge may lie: used pixels whose 8 neighbours are used too. The border of the
    // mask is no edge of the scene: a line cut off by the mirror rim would otherwise close into
    // a small blob that looks like a far ball.
    const cv::Mat& edgeMask() const { return edgeMask_; }
    // 255 where a pixel of the ring is masked (a support rod, a reflection), 0 elsewhere; empty
    // when no pixel of the ring is.
    const cv::Mat& maskedInRing() const { return maskedInRing_; }
    // Distance of each pixel to the robot centre in px (CV_32FC1).
    const cv::Mat& distance() const { return distance_; }
    float distanceAt(int x, int y) const { return distance_.at<float>(y, x); }
    bool isUsed(int x, int y) const { return used_.at<std::uint8_t>(y, x) != 0; }
    // The processed pixels as row spans (fast loops) and as linear offsets (thesis' usedPixels).
    const std::vector<RowSpan>& spans() const { return spans_; }
    const std::vector<int>& usedPixels() const { return usedPixels_; }

private:
    GeometryOptions options_;
    cv::Mat used_;
    cv::Mat edgeMask_;
    cv::Mat maskedInRing_;
    cv::Mat distance_;
    std::vector<RowSpan> spans_;
    std::vector<int> usedPixels_;
};

}  // namespace omnitune
