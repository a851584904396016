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
    // The seeds of `binary` (CV_8UC1, 255 = green or not processed, anything else a non-green
    // processed pixel): 8-connected regions whose pixel count is kMinAreaRatio..kMaxAreaRatio of
    // the ball's disc at their centroid's distance and whose bounding box is no larger than the
    // ball; best fitting first (ties: in raster order of their first pixel), at most maxSeeds.
    // The result lives until the next call. Its buffers are kept: once warm (same image size,
    // maxSeeds no larger) a call allocates nothing.
    // `squashed` (hough.seeds_squashed): the box may be as long as the ball's tangential axis,
    // r / sqrt(squash), where the model squashes the ball radially (a far ball in a spherical
    // mirror is an ellipse twice as wide as deep, wider than a circle of its area-equivalent r).
    const std::vector<BlobSeed>& find(const cv::Mat& binary, const Geometry& geometry, const BallModel& ball, int maxSeeds,
                                      bool squashed = false);

    // A ball partly behind a rod or the robot still counts; a line piece or a robot is larger.
    static constexpr double kMinAreaRatio = 0.35;
    static constexpr double kMaxAreaRatio = 1.6;

private:
    // One region, flooded from its first pixel (`start`, a linear offset) and marked in seen_.
    struct Region {
        int area = 0;
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // bounding box, inclusive
        double cx = 0, cy = 0;               // centroid
    };
    Region flood(const cv::Mat& binary, int start);
    // Keeps `seed` among the best maxSeeds (sorted by fit, stable).
    void keep(const BlobSeed& seed, int maxSeeds);

    cv::Mat seen_;             // CV_8UC1: 1 once a pixel belongs to a flooded region
    std::vector<int> queue_;   // linear offsets of the region being flooded (sized to the image)
    std::vector<BlobSeed> seeds_;
};

}  // namespace omnitune
