#pragma once
// The candidate table as the window shows it: the verdict first, then the scores that explain
// it; the columns that do not fit the narrow cell beside the panes (source, x, y, distance,
// accumulator) are hidden but a right click on the header shows or hides any column.
// Clicking a row reports the candidate's image position.
#include <QPointF>
#include <QTableView>

namespace omnitune {

class CandidateTableModel;

class CandidateTableView : public QTableView {
    Q_OBJECT
public:
    CandidateTableView(CandidateTableModel* model, QWidget* parent = nullptr);

signals:
    void candidateClicked(QPointF imagePos);

private:
    void showColumnMenu(const QPoint& at);

    CandidateTableModel* model_;
};

}  // namespace omnitune
