#include "widgets/PixelInspector.h"

#include "core/ColourClasses.h"
#include "core/DistanceMap.h"

#include <opencv2/imgproc.hpp>

#include <QPointF>

#include <cmath>

namespace omnitune {

QString describePixel(const PipelineRun& run, const Config& config, QPointF imagePos)
{
    const cv::Mat& bgr = run.result.stages.acquired;
    const int x = int(std::floor(imagePos.x()));
    const int y = int(std::floor(imagePos.y()));
    if (bgr.empty() || x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) return {};
    const cv::Vec3b c = bgr.at<cv::Vec3b>(y, x);
    cv::Mat hsv;
    cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar(c[0], c[1], c[2])), hsv, cv::COLOR_BGR2HSV);
    const cv::Vec3b h = hsv.at<cv::Vec3b>(0, 0);
    const auto cls = static_cast<ColorClass>(run.result.classes.at<std::uint8_t>(y, x));
    const std::string className = colourClassName(run.config.colors.classes, cls);
    const auto& g = config.geometry;
    const double d = std::hypot(x - g.centerX, y - g.centerY);
    const bool inRing = d >= g.innerRadius && d <= g.outerRadius;
    const bool masked = !config.mask.empty() && x < config.mask.cols && y < config.mask.rows &&
                        config.mask.at<std::uint8_t>(y, x) == 0;
    QString metres = QStringLiteral("-");
    try {
        metres = QString::number(DistanceMap(config.distanceMap).toGround(d), 'f', 2);
    } catch (const std::exception&) {
    }
    return QStringLiteral("x %1  y %2   BGR %3,%4,%5   HSV %6,%7,%8   class %9   %10 px = %11 m   %12")
        .arg(x)
        .arg(y)
        .arg(c[0])
        .arg(c[1])
        .arg(c[2])
        .arg(h[0])
        .arg(h[1])
        .arg(h[2])
        .arg(QString::fromStdString(className))
        .arg(d, 0, 'f', 1)
        .arg(metres)
        .arg(!inRing ? QStringLiteral("not processed (outside the ring)")
                     : masked ? QStringLiteral("not processed (mask)") : QStringLiteral("processed"));
}

}  // namespace omnitune
