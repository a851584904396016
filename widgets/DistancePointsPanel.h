#pragma once
// The distance map from the window (issue 11): calibration points clicked on the panes (an
// image point whose ground distance was measured: a floor mark, a line crossing with the
// robot at a known pose) with the distance typed in, or loaded from a POINTS.csv; the fit
// (calib/fit/DistanceMapFit, the same as omnitune-calibrate distance-map) written into the
// config as one undo step, or refused with the reason (too few points, a curve that bends
// back) and nothing changed; a plot of points, fit and residuals with the RMS in cm. The
// camera height for the ball-height correction is asked for here too, with what it does.
#include "calib/fit/DistanceMapFit.h"

#include <opencv2/core.hpp>

#include <QPointF>
#include <QWidget>

#include <functional>
#include <optional>

class QDoubleSpinBox;
class QLabel;
class QPainter;
class QPushButton;
class QSpinBox;
class QTableView;

namespace omnitune {

class ConfigDocument;
class DistanceFitPlot;
class DistancePointsModel;
class ImageView;
class PipelineView;

class DistancePointsPanel : public QWidget {
    Q_OBJECT
public:
    // Asks for the ground distance (m) of a clicked image point; nullopt: cancelled.
    using DistanceAsker = std::function<std::optional<double>(QPointF imagePos)>;

    DistancePointsPanel(ConfigDocument* doc, PipelineView* view, QWidget* parent = nullptr);

    bool isAdding() const { return adding_; }
    void setAdding(bool on);
    // Loads POINTS.csv: replaces the points; a file that cannot be used changes nothing.
    bool loadPoints(const QString& path);
    // Fits and writes the map as one undo step; false (with the reason shown) when refused.
    bool fit();
    // Replaces the dialog that asks for a clicked point's distance (tests answer it directly).
    void setDistanceAsker(DistanceAsker asker) { ask_ = std::move(asker); }

    DistancePointsModel* model() const { return model_; }
    DistanceFitPlot* plot() const { return plot_; }
    QString status() const;

signals:
    void addingChanged(bool on);
    void message(const QString& text);  // for the status bar

private:
    void onPressed(QPointF p);
    void ignore(QPointF) {}
    void report(const QString& text, bool problem);
    void showPoints();  // the plot without a fit
    void paintPoints(QPainter& p, const ImageView& pane) const;
    cv::Point2d centre() const;

    ConfigDocument* doc_;
    PipelineView* view_;
    DistancePointsModel* model_;
    DistanceFitPlot* plot_;
    QTableView* table_;
    QPushButton* addButton_;
    QSpinBox* degree_;
    QDoubleSpinBox* height_;
    QLabel* status_;
    bool adding_ = false;
    DistanceAsker ask_;
    std::vector<QWidget*> sketches_;
};

}  // namespace omnitune
