#pragma once
// The calibration points of the distance map as a table (issue 11): image points clicked on
// the panes or loaded from a POINTS.csv (calib/fit/CalibrationPointsCsv), each with its
// measured ground distance, and after a fit the residual of each. Points given as image
// positions get their radius from the robot centre at fit time, so a centre moved afterwards
// moves them too. Emits the documented row signals (tested under QAbstractItemModelTester).
#include "calib/fit/CalibrationPointsCsv.h"

#include <QAbstractTableModel>

#include <vector>

namespace omnitune {

class DistancePointsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { X, Y, Radius, Distance, Residual, ColumnCount };

    explicit DistancePointsModel(QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    void addImagePoint(double x, double y, double distanceM);
    void setPoints(std::vector<CalibrationPoint> points);  // replaces all (a loaded file)
    void removePoint(int row);
    const std::vector<CalibrationPoint>& points() const { return points_; }
    // The fit's input, radii measured from `centre`.
    std::vector<DistancePoint> distancePoints(cv::Point2d centre) const;
    // Residuals (cm, measured minus fitted) in row order; empty clears them.
    void setResiduals(std::vector<double> residualsCm);

private:
    std::vector<CalibrationPoint> points_;
    std::vector<double> residualsCm_;
};

}  // namespace omnitune
