#include "widgets/CandidateTableView.h"

#include "widgets/CandidateTableModel.h"

#include <QHeaderView>
#include <QMenu>

namespace omnitune {

CandidateTableView::CandidateTableView(CandidateTableModel* model, QWidget* parent) : QTableView(parent), model_(model)
{
    setObjectName("candidateTable");
    setModel(model_);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    horizontalHeader()->moveSection(CandidateTableModel::ResultColumn, 1);
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    setFont(small);
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    setToolTip(tr("Candidates of this frame (thesis Table 4.1): click one to centre the panes on it; "
                  "right-click the header for more columns"));
    for (int column : {CandidateTableModel::SourceColumn, CandidateTableModel::XColumn, CandidateTableModel::YColumn,
                       CandidateTableModel::DistanceColumn, CandidateTableModel::AccumulatorColumn})
        hideColumn(column);
    horizontalHeader()->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(horizontalHeader(), &QHeaderView::customContextMenuRequested, this, &CandidateTableView::showColumnMenu);
    connect(this, &QTableView::clicked, this, [this](const QModelIndex& index) {
        const BallCandidate& c = model_->candidate(index.row());
        emit candidateClicked(QPointF(c.x, c.y));
    });
}

void CandidateTableView::showColumnMenu(const QPoint& at)
{
    QMenu menu(this);
    for (int column = 0; column < CandidateTableModel::ColumnCount; ++column) {
        QAction* a = menu.addAction(model_->headerData(column, Qt::Horizontal, Qt::DisplayRole).toString());
        a->setCheckable(true);
        a->setChecked(!isColumnHidden(column));
        connect(a, &QAction::toggled, this, [this, column](bool on) { setColumnHidden(column, !on); });
    }
    menu.exec(horizontalHeader()->mapToGlobal(at));
}

}  // namespace omnitune
