#pragma once
// The automatic camera calibration's convergence, one point per iteration (Qt Charts): the mean
// sample value, the white region's chroma error (U - target and V - target) and the black
// region's level, each with its target as a dashed line, so a user sees the loop settle,
// oscillate or stall at a limit. Display only: the panel feeds it from calibrationIteration.
#include "core/CameraAutoOptions.h"

#include <QWidget>

namespace QtCharts {
class QChart;
class QLineSeries;
class QValueAxis;
}  // namespace QtCharts

namespace omnitune {

class CalibrationPlot : public QWidget {
    Q_OBJECT
public:
    explicit CalibrationPlot(QWidget* parent = nullptr);

    // Targets of the run about to start (camera_auto.msv_target, chroma_target, black_target).
    void setTargets(const CameraAutoOptions& options);
    // Every point gone (a new run starts).
    void clear();
    void addIteration(int iteration, double msv, double u, double v, double black);

    QtCharts::QLineSeries* msvSeries() const { return msv_.series; }
    QtCharts::QLineSeries* uSeries() const { return u_; }
    QtCharts::QLineSeries* vSeries() const { return wb_.series; }
    QtCharts::QLineSeries* blackSeries() const { return black_.series; }

private:
    // One small chart: a measured series against the iteration and its target line.
    struct Chart {
        QtCharts::QChart* chart = nullptr;
        QtCharts::QLineSeries* series = nullptr;
        QtCharts::QLineSeries* target = nullptr;
        QtCharts::QValueAxis* x = nullptr;
        QtCharts::QValueAxis* y = nullptr;
        double targetValue = 0;
    };
    Chart makeChart(const QString& title, const QString& seriesName, QColor colour);
    void setTarget(Chart& c, double value);
    // The axes grown to hold every point and the target (never shrunk during a run).
    void fit(Chart& c, double low, double high);
    void extendTargets(int lastIteration);

    Chart msv_, wb_, black_;
    QtCharts::QLineSeries* u_ = nullptr;  // beside V in the white-balance chart
    double chromaTarget_ = 128.0;
    int regions_ = 5;
};

}  // namespace omnitune
