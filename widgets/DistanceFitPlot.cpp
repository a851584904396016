#include "widgets/DistanceFitPlot.h"

namespace omnitune {

DistanceFitPlot::DistanceFitPlot(QWidget* parent) : CurveFitPlot(parent)
{
    setObjectName(QStringLiteral("distanceFitPlot"));
}

void DistanceFitPlot::setData(std::vector<DistancePoint> points, std::optional<DistanceMapFit> fit)
{
    fit_ = std::move(fit);
    CurveFitPlotData d;
    for (const DistancePoint& q : points) d.samples.emplace_back(q.radiusPx, q.distanceM);
    d.xName = tr("image radius");
    d.xUnit = QStringLiteral("px");
    d.yUnit = QStringLiteral("m");
    d.residualUnit = QStringLiteral("cm");
    d.empty = tr("No calibration points yet");
    if (fit_ && fit_->residualsCm.size() == points.size()) {
        const DistanceMapFit f = *fit_;
        d.residuals = f.residualsCm;
        d.curve = [f](double r) { return f.distanceAt(r); };
        d.curveFrom = f.minRadiusPx;
        d.curveTo = f.maxRadiusPx;
        d.summary = tr("fit: RMS %1 cm, largest %2 cm").arg(f.rmsCm, 0, 'f', 1).arg(f.maxAbsCm, 0, 'f', 1);
    }
    setPlot(std::move(d));
}

}  // namespace omnitune
