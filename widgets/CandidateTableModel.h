#pragma once
// The ball candidates of one pipeline result as a table (thesis Table 4.1, extended): where
// each candidate is, its radius and Hough votes, its three validation scores and the test that
// rejected it. The accepted ball's row is highlighted; in a rejected row the failing cell is
// red. Tooltips explain each column and the threshold it was compared against.
#include "core/BallCandidate.h"
#include "core/PipelineResult.h"
#include "core/Validation.h"

#include <QAbstractTableModel>

#include <vector>

namespace omnitune {

struct Config;

class CandidateTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        AreaColumn,
        SourceColumn,
        XColumn,
        YColumn,
        RadiusColumn,
        DistanceColumn,
        AccumulatorColumn,
        NonGreenColumn,
        NonBlackColumn,
        CircularityColumn,
        RunOnColumn,
        ResultColumn,
        ColumnCount
    };
    // Qt::UserRole: the cell's raw value (number or text) for sorting and plotting.
    static constexpr int SortRole = Qt::UserRole;

    explicit CandidateTableModel(QObject* parent = nullptr);

    // Replaces all rows (a model reset). `config`: the one the result was computed with; its
    // thresholds (validation.*, hough.min_accumulator, opencv_hough.max_radius_ratio) are the
    // ones the tooltips quote, so they always match the scores shown.
    void setResult(const PipelineResult& result, const Config& config);
    void clear();

    const BallCandidate& candidate(int row) const;
    // Whether the row is a refusal of the candidate prefilter (hough.prefilter_*): judged on its
    // square's colour or the rim before validation, so its circularity and run-on were never
    // measured (shown as "-").
    bool isPrefiltered(int row) const;
    // Whether the row is a prefilter refusal that validation.recentre_refused moved to the
    // centroid of what is not carpet, where it passed validation.
    bool isRecentred(int row) const;
    // Row of the accepted ball, -1 when none was accepted.
    int acceptedRow() const;
    // The column holding the score that rejected the candidate, -1 when none does (accepted,
    // valid but not chosen, outside the processed area).
    static int failingColumn(RejectReason reason);

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    struct Thresholds {
        ValidationOptions validation;
        int minAccumulator;
        double maxRadiusRatio;
    };

    void setThresholds(const Config& config);
    QVariant display(const BallCandidate& c, int column) const;
    QVariant sortValue(const BallCandidate& c, int column) const;
    QString columnToolTip(int column) const;
    // Where a row came from: the searches, or the prefilter's refusals listed at the end of the
    // specific search's rows.
    enum class RowKind : unsigned char { Searched, Prefiltered };
    RowKind kindOf(int row) const;
    QString cellToolTip(const BallCandidate& c, int column, RowKind kind) const;

    std::vector<BallCandidate> candidates_;
    std::vector<RowKind> kinds_;  // per row
    Thresholds thresholds_;
};

}  // namespace omnitune
