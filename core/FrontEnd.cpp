#include "core/FrontEnd.h"

#include "core/FillBytes.h"
#include "core/SpeckFreeEdges.h"
#include "core/Stopwatch.h"

#include <opencv2/core.hpp>


namespace omnitune {

FrontEnd::FrontEnd(const Config& config)
    : lut_(config.colors), roles_(config.colors.classes), geometry_(config.geometry, config.mask), edgeOptions_(config.edges),
      cannyOptions_(speckFreeCannyOptions(config.edges))
{
}

void FrontEnd::process(const cv::Mat& frame, PixelFormat format, cv::Mat& classes, cv::Mat& binary, cv::Mat& edges,
                       StageTimings* timings)
{
    CV_Assert(frame.size() == geometry_.imageSize());
    Stopwatch clock;
    classes.create(geometry_.imageSize(), CV_8UC1);
    fillBytes(classes, 0);
    lut_.segment(frame, format, geometry_.spans(), classes, &stats_);
    const double segmentMs = clock.lap();
    makeBinary(classes, geometry_, binary, edgeOptions_.whiteLevel, roles_);
    if (edgeOptions_.input == EdgeInput::Gray) makeGray(frame, format == PixelFormat::Uyvy, gray_);
    const double binaryMs = clock.lap();
    canny_.detect(edgeSource(binary), cannyOptions_, edges);
    cv::bitwise_and(edges, geometry_.edgeMask(), edges);
    const double edgesMs = clock.lap();
    if (timings) {
        timings->segmentMs = segmentMs;
        timings->binaryMs = binaryMs;
        timings->edgesMs = edgesMs;
    }
}

}  // namespace omnitune
