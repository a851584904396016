#pragma once
// The camera panel's live intensity histogram: one bar per region of the mean sample value
// (calib/camera/MeanSampleValue), its share of the counted pixels, and a marker where the MSV
// and its target fall on the same 1..regions scale, so a user sees at a glance whether the
// image is too dark (bars on the left) or clipping (a tall last bar). Display only.
#include <QWidget>

#include <vector>

namespace omnitune {

class IntensityHistogramView : public QWidget {
    Q_OBJECT
public:
    explicit IntensityHistogramView(QWidget* parent = nullptr);

    // Pixels per region (any number of regions; empty: nothing to show), the MSV, its target
    // and the tolerance accepted around it.
    void setHistogram(std::vector<double> histogram, double msv, double target, double tolerance);
    void clear();
    const std::vector<double>& histogram() const { return histogram_; }
    double msv() const { return msv_; }

    QSize sizeHint() const override { return {240, 90}; }
    QSize minimumSizeHint() const override { return {120, 60}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::vector<double> histogram_;
    double msv_ = 0, target_ = 0, tolerance_ = 0;
};

}  // namespace omnitune
