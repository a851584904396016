#include "widgets/CandidateTableModel.h"

#include "core/Config.h"
#include "core/PrefilterRefusals.h"

#include <QBrush>
#include <QColor>
#include <QFont>

#include <algorithm>

namespace omnitune {

namespace {

// Fixed light backgrounds with matching dark text, readable under light and dark themes.
const QColor kAcceptedBackground(198, 239, 206);
const QColor kAcceptedText(0, 97, 0);
const QColor kFailedBackground(255, 199, 206);
const QColor kFailedText(156, 0, 6);

QString number(double v, int decimals) { return QString::number(v, 'f', decimals); }

bool isRejected(RejectReason r) { return r != RejectReason::None && r != RejectReason::NotChosen; }

// A score validation never computed shows "-" and sorts as empty, not as a failing 0: the
// prefilter's refusals have no shape, and a pipeline that does not explain its rejections stops
// at a failed colour test (Pipeline::setExplainRejections).
bool wasMeasured(const BallCandidate& c, int column)
{
    switch (column) {
    case CandidateTableModel::NonGreenColumn:
    case CandidateTableModel::NonBlackColumn: return c.scores.squareMeasured;
    case CandidateTableModel::CircularityColumn:
    case CandidateTableModel::RunOnColumn: return c.scores.shapeMeasured;
    default: return true;
    }
}

}  // namespace

CandidateTableModel::CandidateTableModel(QObject* parent) : QAbstractTableModel(parent)
{
    setThresholds(Config{});
}

void CandidateTableModel::setResult(const PipelineResult& result, const Config& config)
{
    beginResetModel();
    candidates_ = result.candidates;
    // The recentred refusals that passed are validated candidates now and say so themselves
    // (BallCandidate::move).
    const std::vector<bool> refused = prefilterRefusals(result);
    kinds_.assign(candidates_.size(), RowKind::Searched);
    for (std::size_t i = 0; i < refused.size(); ++i)
        if (refused[i]) kinds_[i] = RowKind::Prefiltered;
    setThresholds(config);
    endResetModel();
}

void CandidateTableModel::clear()
{
    beginResetModel();
    candidates_.clear();
    kinds_.clear();
    endResetModel();
}

// Inside a model reset (or the constructor): views read everything again afterwards.
void CandidateTableModel::setThresholds(const Config& config)
{
    thresholds_ = Thresholds{config.validation, config.hough.minAccumulator, config.opencvHough.maxRadiusRatio};
}

CandidateTableModel::RowKind CandidateTableModel::kindOf(int row) const
{
    return row >= 0 && std::size_t(row) < kinds_.size() ? kinds_[std::size_t(row)] : RowKind::Searched;
}

bool CandidateTableModel::isPrefiltered(int row) const { return kindOf(row) == RowKind::Prefiltered; }

bool CandidateTableModel::isRecentred(int row) const
{
    return row >= 0 && std::size_t(row) < candidates_.size() &&
           candidates_[std::size_t(row)].move == CandidateMove::ToColourCentroid;
}

const BallCandidate& CandidateTableModel::candidate(int row) const
{
    Q_ASSERT(row >= 0 && row < rowCount());
    return candidates_[std::size_t(row)];
}

int CandidateTableModel::acceptedRow() const
{
    for (std::size_t i = 0; i < candidates_.size(); ++i)
        if (candidates_[i].rejected == RejectReason::None) return int(i);
    return -1;
}

int CandidateTableModel::failingColumn(RejectReason reason)
{
    switch (reason) {
    case RejectReason::RadiusTooLarge:
    case RejectReason::TooSmall: return RadiusColumn;
    case RejectReason::NonGreen: return NonGreenColumn;
    case RejectReason::NonBlack: return NonBlackColumn;
    case RejectReason::Circularity: return CircularityColumn;
    case RejectReason::RunsOn: return RunOnColumn;
    case RejectReason::None:
    case RejectReason::OutsideArea:
    case RejectReason::LineBlob:
    case RejectReason::LineJunction:  // no score of its own: the result's tooltip says why
    case RejectReason::NotChosen: return -1;
    }
    return -1;
}

int CandidateTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(candidates_.size());
}

int CandidateTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant CandidateTableModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid)) return {};
    const BallCandidate& c = candidates_[std::size_t(index.row())];
    const RowKind kind = kindOf(index.row());
    const int column = index.column();
    const bool accepted = c.rejected == RejectReason::None;
    const bool failed = isRejected(c.rejected) && column == failingColumn(c.rejected);
    switch (role) {
    case Qt::DisplayRole: return display(c, column);
    case SortRole: return sortValue(c, column);
    case Qt::ToolTipRole: return cellToolTip(c, column, kind);
    case Qt::TextAlignmentRole:
        return column == SourceColumn || column == ResultColumn ? int(Qt::AlignLeft | Qt::AlignVCenter)
                                                                 : int(Qt::AlignRight | Qt::AlignVCenter);
    case Qt::BackgroundRole:
        if (accepted) return QBrush(kAcceptedBackground);
        if (failed) return QBrush(kFailedBackground);
        return {};
    case Qt::ForegroundRole:
        if (accepted) return QBrush(kAcceptedText);
        if (failed || (column == ResultColumn && isRejected(c.rejected))) return QBrush(kFailedText);
        return {};
    case Qt::FontRole:
        if (accepted) {
            QFont font;
            font.setBold(true);
            return font;
        }
        return {};
    default: return {};
    }
}

QVariant CandidateTableModel::display(const BallCandidate& c, int column) const
{
    const bool specific = c.source == CandidateSource::SpecificHough;
    if (!wasMeasured(c, column)) return QStringLiteral("-");
    switch (column) {
    case AreaColumn: return c.area >= 0 ? QString::number(c.area + 1) : QStringLiteral("-");
    case SourceColumn: return QString::fromUtf8(candidateSourceName(c.source).data(), int(candidateSourceName(c.source).size()));
    case XColumn: return QString::number(c.x);
    case YColumn: return QString::number(c.y);
    case RadiusColumn: return number(c.radiusPx, 1);
    case DistanceColumn: return number(c.distancePx, 1);
    case AccumulatorColumn: return specific ? number(c.accumulator, 0) : QStringLiteral("-");  // blobs and circles: no votes
    case NonGreenColumn: return number(c.scores.nonGreenPct, 1);
    case NonBlackColumn: return number(c.scores.nonBlackPct, 1);
    case CircularityColumn: return number(c.scores.circularityPct, 1);
    case RunOnColumn: return number(c.scores.runOnPct, 1);
    case ResultColumn: {
        // A moved row is not where its search put it: said in the verdict, the column always shown
        // (the tooltip says from where and why).
        const QString verdict = QString::fromUtf8(rejectReasonName(c.rejected).data(), int(rejectReasonName(c.rejected).size()));
        return c.move == CandidateMove::None ? verdict : tr("%1, moved").arg(verdict);
    }
    }
    return {};
}

QVariant CandidateTableModel::sortValue(const BallCandidate& c, int column) const
{
    if (!wasMeasured(c, column)) return {};
    switch (column) {
    case AreaColumn: return c.area;
    case SourceColumn:
    case ResultColumn: return display(c, column);
    case XColumn: return c.x;
    case YColumn: return c.y;
    case RadiusColumn: return c.radiusPx;
    case DistanceColumn: return c.distancePx;
    case AccumulatorColumn: return c.accumulator;
    case NonGreenColumn: return c.scores.nonGreenPct;
    case NonBlackColumn: return c.scores.nonBlackPct;
    case CircularityColumn: return c.scores.circularityPct;
    case RunOnColumn: return c.scores.runOnPct;
    }
    return {};
}

QVariant CandidateTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || section < 0 || section >= ColumnCount)
        return QAbstractTableModel::headerData(section, orientation, role);
    if (role == Qt::ToolTipRole) return columnToolTip(section);
    if (role != Qt::DisplayRole) return {};
    switch (section) {
    case AreaColumn: return tr("Area");
    case SourceColumn: return tr("Source");
    case XColumn: return tr("x");
    case YColumn: return tr("y");
    // Two-line headers: the scores and the verdict must fit the narrow cell beside the panes.
    case RadiusColumn: return tr("r\n(px)");
    case DistanceColumn: return tr("Distance (px)");
    case AccumulatorColumn: return tr("Accumulator");
    case NonGreenColumn: return tr("non-\ngreen %");
    case NonBlackColumn: return tr("non-\nblack %");
    case CircularityColumn: return tr("circ.\n%");
    case RunOnColumn: return tr("run-\non %");
    case ResultColumn: return tr("Result");
    }
    return {};
}

QString CandidateTableModel::columnToolTip(int column) const
{
    const Thresholds& t = thresholds_;
    switch (column) {
    case AreaColumn:
        return tr("Radial area of the specific Hough transform, 1 = innermost (outer bounds: hough.area_bounds); "
                  "one maximum per area with hough.multiple_maxima. \"-\": an OpenCV circle or the single absolute maximum.");
    case SourceColumn: return tr("Which search found it: the specific Hough transform (thesis 4.1) or cv::HoughCircles (4.2).");
    case XColumn:
    case YColumn: return tr("Centre of the candidate in the image, px.");
    case RadiusColumn:
        return tr("Expected ball radius at the centre's distance (specific) or the circle's own radius (OpenCV), px. "
                  "A candidate whose expected radius is below %1 px (validation.min_radius_px) is too far to validate; "
                  "an OpenCV circle larger than %2 x the expected radius (opencv_hough.max_radius_ratio) is rejected.")
            .arg(number(t.validation.minRadiusPx, 1), number(t.maxRadiusRatio, 2));
    case DistanceColumn: return tr("Distance of the centre from the robot centre, px; the expected radius follows from it.");
    case AccumulatorColumn:
        return tr("Sum of the Hough votes in the 3x3 neighbourhood of the maximum; maxima below %1 (hough.min_accumulator) "
                  "give no candidate. OpenCV circles carry no votes (\"-\").")
            .arg(t.minAccumulator);
    case NonGreenColumn:
        return tr("Share of the processed pixels in the ball square that are not green; a ball needs at least %1 % "
                  "(validation.min_non_green_pct). Carpet patches fail it.")
            .arg(number(t.validation.minNonGreenPct, 1));
    case NonBlackColumn:
        return tr("Share of the processed pixels in the ball square that are not black; a ball needs at least %1 % "
                  "(validation.min_non_black_pct). Black robots fail it.")
            .arg(number(t.validation.minNonBlackPct, 1));
    case CircularityColumn:
        return tr("Share of the rays from the centre that meet an edge at the expected radius +- %1 % "
                  "(validation.radius_tolerance); a ball needs at least %2 % (validation.min_circularity_pct), or "
                  "%3 % in the clear: its square at least %4 % non-black, its expected radius at least %5 px and "
                  "its fitted radius within %6 % of it (validation.min_circularity_clear_pct). Lines, corners and "
                  "feet fail it.")
            .arg(number(t.validation.radiusTolerance * 100.0, 0), number(t.validation.minCircularityPct, 1),
                 number(std::min(t.validation.minCircularityPct, t.validation.minCircularityClearPct), 1),
                 number(t.validation.clearMinNonBlackPct, 1), number(t.validation.clearMinRadiusPx, 1),
                 number(t.validation.clearMaxFitError * 100.0, 0));
    case RunOnColumn:
        return tr("Share of the rays along which the centre's colour runs on without a break beyond the circle; at most "
                  "%1 % (validation.max_run_on_pct). A ball has carpet just outside its border; line corners fail it.")
            .arg(number(t.validation.maxRunOnPct, 1));
    case ResultColumn:
        return tr("\"accepted\", or the first test that rejected the candidate: too far to validate, then the thesis' "
                  "non-green, non-black, circularity, then run-on, \"line junction\" (field lines leave it like "
                  "spokes, validation.line_arms) and \"line blob\" (no arm, mostly line colour inside: a line's end or "
                  "the penalty spot); \"valid, not chosen\": it passed, but another candidate scored higher.");
    }
    return {};
}

QString CandidateTableModel::cellToolTip(const BallCandidate& c, int column, RowKind kind) const
{
    QString tip = columnToolTip(column);
    const bool shapeColumn = column == CircularityColumn || column == RunOnColumn || column == ResultColumn;
    if (kind == RowKind::Prefiltered && shapeColumn)
        tip += tr("\nNot validated: the candidate prefilter (hough.prefilter_*) refused it on its square's colour or "
                  "at the mirror rim, so its shape was never measured.");
    const bool moveColumn = column == SourceColumn || column == XColumn || column == YColumn || column == ResultColumn;
    if (c.move != CandidateMove::None && moveColumn) {
        const QString how =
            c.move == CandidateMove::ToColourCentroid
                ? tr("Recentred from (%1, %2): the prefilter refused the Hough maximum there on its square's colour (a "
                     "green-and-white ball's maximum lies on its white half); moved to the centroid of what is not "
                     "carpet and validated here (validation.recentre_refused).")
                : tr("Moved to its fit from (%1, %2): the Hough maximum there failed circularity, but its border fits "
                     "a circle centred here (a rod or the ball's panels pulled the votes off centre); validated again "
                     "here (validation.refit_recentre).");
        tip += QLatin1Char('\n') + how.arg(c.searchX).arg(c.searchY);
    }
    if (column == RadiusColumn && c.expectedRadiusPx > 0.0)
        tip += tr("\nExpected radius here: %1 px.").arg(number(c.expectedRadiusPx, 1));
    if (!isRejected(c.rejected) || column != failingColumn(c.rejected)) return tip;
    const Thresholds& t = thresholds_;
    QString why;
    switch (c.rejected) {
    case RejectReason::NonGreen:
        why = tr("%1 % is below %2 %").arg(number(c.scores.nonGreenPct, 1), number(t.validation.minNonGreenPct, 1));
        break;
    case RejectReason::NonBlack:
        why = tr("%1 % is below %2 %").arg(number(c.scores.nonBlackPct, 1), number(t.validation.minNonBlackPct, 1));
        break;
    case RejectReason::Circularity:
        why = tr("%1 % is below %2 %")
                  .arg(number(c.scores.circularityPct, 1), number(requiredCircularityPct(c, t.validation), 1));
        break;
    case RejectReason::TooSmall:
        why = tr("expected radius %1 px is below %2 px")
                  .arg(number(c.expectedRadiusPx, 1), number(t.validation.minRadiusPx, 1));
        break;
    case RejectReason::RunsOn:
        why = tr("%1 % is above %2 %").arg(number(c.scores.runOnPct, 1), number(t.validation.maxRunOnPct, 1));
        break;
    case RejectReason::RadiusTooLarge:
        why = tr("radius %1 px is above %2 x %3 px expected")
                  .arg(number(c.radiusPx, 1), number(t.maxRadiusRatio, 2), number(c.expectedRadiusPx, 1));
        break;
    default: break;
    }
    return tip + tr("\nRejected here: %1.").arg(why);
}

}  // namespace omnitune
