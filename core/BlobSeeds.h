#pragma once
// Candidate seeds that need no votes: compact connected non-green regions of the ball's size at
// their distance (hough.blob_seeds). A ball whose edges are out-voted in its radial area by
// clutter (speckle in dim light, a robot, the rim) is still one blob of the right size.
#include <opencv2/core.hpp>

#include <vector>

namespace omnitune {

class Geometry;
class BallModel;

struct BlobSeed {
    int x;       // centroid, px
    int y;
    double fit;  // |ln(pixel count / ball disc)|: 0 is a perfect size match
};

class BlobSeeds {
public:
    // The seeds of `binary` (CV_8UC1, 0 = non-green and processed): 8-connected regions whose
    // pixel count is kMinAreaRatio..kMaxAreaRatio of the ball's disc at their centroid's
    // distance and whose bounding box is no larger than the ball; best fitting first, at most
    // maxSeeds. The result lives until the next call.
    const std::vector<BlobSeed>& find(const cv::Mat& binary, const Geometry& geometry, const BallModel& ball, int maxSeeds);

    // A ball partly behind a rod or the robot still counts; a line piece or a robot is larger.
    static constexpr double kMinAreaRatio = 0.35;
    static constexpr double kMaxAreaRatio = 1.6;

private:
    cv::Mat nonGreen_;
    cv::Mat labels_;
    cv::Mat stats_;
    cv::Mat centroids_;
    std::vector<BlobSeed> seeds_;
};

}  // namespace omnitune
