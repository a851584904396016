#include "widgets/DistancePointsModel.h"

namespace omnitune {

DistancePointsModel::DistancePointsModel(QObject* parent) : QAbstractTableModel(parent) {}

int DistancePointsModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : int(points_.size()); }

int DistancePointsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant DistancePointsModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount()) return {};
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    const CalibrationPoint& p = points_[std::size_t(index.row())];
    switch (index.column()) {
    case X: return p.fromImagePoint ? QString::number(p.xPx, 'f', 1) : QString();
    case Y: return p.fromImagePoint ? QString::number(p.yPx, 'f', 1) : QString();
    case Radius: return p.fromImagePoint ? QString() : QString::number(p.radiusPx, 'f', 1);
    case Distance: return QString::number(p.distanceM, 'f', 3);
    case Residual:
        return std::size_t(index.row()) < residualsCm_.size() ? QString::number(residualsCm_[std::size_t(index.row())], 'f', 1)
                                                              : QString();
    default: return {};
    }
}

QVariant DistancePointsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    switch (section) {
    case X: return tr("x (px)");
    case Y: return tr("y (px)");
    case Radius: return tr("r (px)");
    case Distance: return tr("ground (m)");
    case Residual: return tr("residual (cm)");
    default: return {};
    }
}

void DistancePointsModel::addImagePoint(double x, double y, double distanceM)
{
    setResiduals({});  // they belonged to the fit without this point
    const int row = rowCount();
    beginInsertRows({}, row, row);
    CalibrationPoint p;
    p.fromImagePoint = true;
    p.xPx = x;
    p.yPx = y;
    p.distanceM = distanceM;
    points_.push_back(p);
    endInsertRows();
}

void DistancePointsModel::setPoints(std::vector<CalibrationPoint> points)
{
    beginResetModel();
    points_ = std::move(points);
    residualsCm_.clear();
    endResetModel();
}

void DistancePointsModel::removePoint(int row)
{
    if (row < 0 || row >= rowCount()) return;
    setResiduals({});
    beginRemoveRows({}, row, row);
    points_.erase(points_.begin() + row);
    endRemoveRows();
}

std::vector<DistancePoint> DistancePointsModel::distancePoints(cv::Point2d centre) const
{
    return toDistancePoints(points_, centre);
}

void DistancePointsModel::setResiduals(std::vector<double> residualsCm)
{
    if (residualsCm.empty() && residualsCm_.empty()) return;
    residualsCm_ = std::move(residualsCm);
    if (rowCount() > 0) emit dataChanged(index(0, Residual), index(rowCount() - 1, Residual));
}

}  // namespace omnitune
