#pragma once
// The distance map's calibration points, the fitted curve and the residuals (issue 11): ground
// distance over image radius on top, the residual of each point (cm) below, with the RMS, so a
// point typed wrong or a curve that bends stands out.
#include "calib/fit/DistanceMapFit.h"
#include "widgets/CurveFitPlot.h"

#include <optional>
#include <vector>

namespace omnitune {

class DistanceFitPlot : public CurveFitPlot {
    Q_OBJECT
public:
    explicit DistanceFitPlot(QWidget* parent = nullptr);

    // Points alone (no fit yet, or a refused one), or points with their fit.
    void setData(std::vector<DistancePoint> points, std::optional<DistanceMapFit> fit);
    const std::optional<DistanceMapFit>& fit() const { return fit_; }

private:
    std::optional<DistanceMapFit> fit_;
};

}  // namespace omnitune
