#pragma once
// Hand-checkable test scenes for the core tests: a flat green field with shapes drawn at
// known places, in the geometry of a Config. (Realistic scenes come from calib's simulator.)
#include "core/BallModel.h"
#include "core/Config.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace omnitune::test {

inline const cv::Scalar kGreen(40, 140, 40);
inline const cv::Scalar kWhite(235, 235, 235);
inline const cv::Scalar kBlack(20, 20, 20);
inline const cv::Scalar kOrange(20, 110, 240);

inline cv::Mat greenField(const Config& c)
{
    return cv::Mat(c.geometry.imageHeight, c.geometry.imageWidth, CV_8UC3, kGreen);
}

// Image point at `distance` px from the robot centre, `angleDeg` counter-clockwise from +x.
inline cv::Point2d pointAt(const Config& c, double distance, double angleDeg)
{
    const double a = angleDeg * M_PI / 180.0;
    return {c.geometry.centerX + distance * std::cos(a), c.geometry.centerY - distance * std::sin(a)};
}

// The unit vector away from the robot centre at `angleDeg` (as pointAt: image y points down).
inline cv::Point2d radialAt(double angleDeg)
{
    const double a = angleDeg * M_PI / 180.0;
    return {std::cos(a), -std::sin(a)};
}

// The pixel nearest to `p`.
inline cv::Point rounded(const cv::Point2d& p)
{
    return {int(std::lround(p.x)), int(std::lround(p.y))};
}

inline double expectedRadius(const Config& c, double distance)
{
    return BallModel(c.ball).radiusAt(distance);
}

// A filled disc of the ball model's radius at the given distance and angle; returns its centre.
inline cv::Point drawBall(cv::Mat& img, const Config& c, double distance, double angleDeg,
                          const cv::Scalar& color = kOrange)
{
    const cv::Point2d p = pointAt(c, distance, angleDeg);
    const cv::Point centre(int(std::lround(p.x)), int(std::lround(p.y)));
    cv::circle(img, centre, int(std::lround(expectedRadius(c, distance))), color, cv::FILLED, cv::LINE_8);
    return centre;
}

}  // namespace omnitune::test

#include "core/FrontEnd.h"

namespace omnitune::test {

// The stages before the Hough transform on a drawn frame: the product's own front end, so the
// edge, Hough and validation tests run on what the pipeline runs.
struct EdgeStages {
    FrontEnd frontEnd;
    const Geometry& geometry;
    BallModel ball;
    cv::Mat classes;
    cv::Mat binary;
    cv::Mat edges;

    EdgeStages(const Config& c, const cv::Mat& frame) : frontEnd(c), geometry(frontEnd.geometry()), ball(c.ball)
    {
        frontEnd.process(frame, PixelFormat::Bgr8, classes, binary, edges);
    }
};

}  // namespace omnitune::test
