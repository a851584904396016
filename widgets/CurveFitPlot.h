#pragma once
// A fitted curve over its samples, with the residuals below (issue 11): y over x on top, each
// sample's residual in a strip underneath, scaled to the largest, with a one-line summary (the
// RMS). The distance map (DistanceFitPlot) and the ball model (BallModelPanel) both plot
// through it, each in its own units.
#include <QPointF>
#include <QString>
#include <QWidget>

#include <functional>
#include <vector>

namespace omnitune {

struct CurveFitPlotData {
    std::vector<QPointF> samples;        // (x, y) in the axes' units
    std::vector<double> residuals;       // per sample, in residualUnit; empty: no fit yet
    std::function<double(double)> curve;  // y(x); empty: no fit yet
    double curveFrom = 0.0, curveTo = 0.0;  // x span the curve is drawn over
    QString xName = QStringLiteral("x");    // "image radius" (its unit follows: "px")
    QString xUnit, yUnit, residualUnit;
    QString summary;                      // "fit: RMS 1.2 cm, largest 3.0 cm"
    QString empty;                        // shown when there are no samples
};

class CurveFitPlot : public QWidget {
    Q_OBJECT
public:
    explicit CurveFitPlot(QWidget* parent = nullptr);
    void setPlot(CurveFitPlotData data);
    const CurveFitPlotData& plotData() const { return data_; }
    QSize sizeHint() const override { return QSize(320, 240); }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    CurveFitPlotData data_;
};

}  // namespace omnitune
