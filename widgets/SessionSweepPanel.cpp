#include "widgets/SessionSweepPanel.h"

#include "widgets/FrameNavigator.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace omnitune {

namespace {

enum Row { FramesRow, FoundRow, RatioRow, FalsePositiveRow, TimeRow, RowCount };

QString pct(double value) { return QStringLiteral("%1 %").arg(value, 0, 'f', 1); }

// Short cells: two columns of them must fit a dialog beside the window.
QString framesCell(const EvaluationRow& row)
{
    return row.failed ? QObject::tr("%1 (%2 failed)").arg(row.frames).arg(row.failed) : QString::number(row.frames);
}

QString foundCell(const std::vector<FrameOutcome>& outcomes, const EvaluationRow& row)
{
    const int found = detectionCount(outcomes);
    return QObject::tr("%1 (%2)").arg(found).arg(pct(row.frames ? 100.0 * found / row.frames : 0.0));
}

QString ratioCell(const EvaluationRow& row)
{
    return QObject::tr("%1 (%2 / %3)").arg(pct(row.detectionRatioPct)).arg(row.correct).arg(row.withBall);
}

QString falsePositiveCell(const EvaluationRow& row)
{
    return QObject::tr("%1 (%2)").arg(row.falsePositives).arg(pct(row.falsePositivePct));
}

QString timeCell(const EvaluationRow& row)
{
    return QObject::tr("%1 ms (%2 to %3)").arg(row.timeAvgMs, 0, 'f', 1).arg(row.timeMinMs, 0, 'f', 1).arg(row.timeMaxMs, 0, 'f', 1);
}

QString changeLine(const FrameComparison& c)
{
    if (c.change == FrameChange::Moved)
        return QObject::tr("Frame %1: moved %2 px").arg(c.frame).arg(c.shiftPx, 0, 'f', 0);
    return QObject::tr("Frame %1: %2").arg(c.frame).arg(frameChangeName(c.change));
}

}  // namespace

SessionSweepPanel::SessionSweepPanel(FrameNavigator* navigator, QWidget* parent)
    : QWidget(parent), navigator_(navigator), status_(new QLabel(this)), progressBar_(new QProgressBar(this)),
      cancelButton_(new QPushButton(tr("Cancel"), this)), note_(new QLabel(this)), table_(new QTableWidget(RowCount, 2, this)),
      changes_(new QLabel(this)), changeList_(new QListWidget(this)),
      previousButton_(new QPushButton(tr("Previous"), this)), nextButton_(new QPushButton(tr("Next"), this)),
      outdatedNote_(new QLabel(this)), rerunButton_(new QPushButton(tr("Apply again"), this))
{
    setObjectName("sessionSweepPanel");
    status_->setObjectName("status");
    status_->setWordWrap(true);
    progressBar_->setObjectName("progress");
    progressBar_->setFormat(tr("%v / %m frames"));
    cancelButton_->setObjectName("cancel");
    note_->setObjectName("note");
    note_->setWordWrap(true);
    table_->setObjectName("numbers");
    table_->setHorizontalHeaderLabels({tr("Current config"), tr("Saved config")});
    table_->setVerticalHeaderLabels({tr("Frames"), tr("Ball detected in"), tr("Detection ratio"),
                                     tr("False positives"), tr("Time per frame")});
    // The header's tooltips say what each number counts.
    const QString tips[RowCount] = {
        tr("Frames processed (and how many could not be read or processed)"),
        tr("Frames where the detector accepted a ball, right or wrong"),
        tr("Ball frames of truth.csv with a detection within 0.5 m of the truth (correct / ball frames)"),
        tr("Detections in frames without a ball, or more than 0.5 m from the truth (count, share of marked frames)"),
        tr("Pipeline time per frame: average (min to max); measured while the window works too, so "
           "use omnitune-eval or bench/ for exact numbers")};
    for (int i = 0; i < RowCount; ++i) table_->verticalHeaderItem(i)->setToolTip(tips[i]);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    table_->setFocusPolicy(Qt::NoFocus);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    changes_->setObjectName("changes");
    changes_->setWordWrap(true);
    changeList_->setObjectName("changeList");
    changeList_->setToolTip(tr("Click a frame to show it"));
    previousButton_->setObjectName("previousChange");
    nextButton_->setObjectName("nextChange");
    outdatedNote_->setObjectName("outdated");
    outdatedNote_->setWordWrap(true);
    outdatedNote_->setStyleSheet("color: #b35900");
    outdatedNote_->setText(tr("The config changed after this run: these numbers and the slider marks (now faint) "
                              "describe the earlier config. Apply again to update them."));
    rerunButton_->setObjectName("rerun");
    rerunButton_->setToolTip(tr("Run the current config over every frame again (Ctrl+R)"));
    previousButton_->setToolTip(tr("Show the previous changed frame"));
    nextButton_->setToolTip(tr("Show the next changed frame"));

    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(progressBar_, 1);
    progressRow->addWidget(cancelButton_);
    auto* jumpRow = new QHBoxLayout;
    jumpRow->addWidget(previousButton_);
    jumpRow->addWidget(nextButton_);
    jumpRow->addStretch(1);
    auto* statusRow = new QHBoxLayout;
    statusRow->addWidget(status_, 1);
    statusRow->addWidget(rerunButton_, 0, Qt::AlignTop);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(statusRow);
    layout->addLayout(progressRow);
    layout->addWidget(note_);
    layout->addWidget(table_);
    layout->addWidget(changes_);
    layout->addWidget(changeList_, 1);
    layout->addLayout(jumpRow);
    layout->addStretch(0);  // takes the room of the change list when there is none
    layout->addWidget(outdatedNote_);

    connect(cancelButton_, &QPushButton::clicked, this, &SessionSweepPanel::cancel);
    connect(previousButton_, &QPushButton::clicked, this, &SessionSweepPanel::previousChange);
    connect(nextButton_, &QPushButton::clicked, this, &SessionSweepPanel::nextChange);
    connect(rerunButton_, &QPushButton::clicked, this, &SessionSweepPanel::rerunRequested);
    connect(changeList_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        navigator_->goTo(item->data(Qt::UserRole).toInt());
    });
    reset();
}

SessionSweepPanel::~SessionSweepPanel() = default;  // ~SessionSweep cancels and waits

void SessionSweepPanel::start(SweepRequest request)
{
    sweep_.reset();  // a sweep still running is cancelled and joined first
    const quint64 run = ++runId_;
    status_->setText(tr("Running the current config over %1...").arg(QFileInfo(request.sourcePath).fileName()));
    sweep_ = std::make_unique<SessionSweep>(std::move(request));
    // A late signal of an earlier sweep (already queued when it was replaced) is dropped.
    connect(sweep_.get(), &SessionSweep::progress, this, [this, run](int done, int total) {
        if (run == runId_) onProgress(done, total);
    });
    connect(sweep_.get(), &SessionSweep::finished, this, [this, run](std::shared_ptr<const SweepResult> r) {
        if (run == runId_) onFinished(std::move(r));
    });
    outdated_ = false;
    outdatedNote_->hide();
    showRunning(true);
    sweep_->start();
}

void SessionSweepPanel::cancel()
{
    if (!sweep_) return;
    sweep_->cancel();
    cancelButton_->setEnabled(false);
    status_->setText(tr("Cancelling..."));
}

void SessionSweepPanel::reset()
{
    sweep_.reset();
    ++runId_;
    result_.reset();
    outdated_ = false;
    status_->setText(tr("Press Apply again to run the current config over every frame."));
    showRunning(false);
    showResult();
}

void SessionSweepPanel::setOutdated(bool outdated)
{
    // During a sweep too: its config was copied at the start, so an edit since then makes the
    // coming result outdated as well.
    outdated_ = outdated && (result_ || sweep_);
    outdatedNote_->setVisible(outdated_ && !sweep_);
}

void SessionSweepPanel::onProgress(int done, int total)
{
    progressBar_->setRange(0, std::max(total, 0));  // 0..0: busy, length unknown
    progressBar_->setValue(done);
    emit sweepProgress(done, total);
}

void SessionSweepPanel::onFinished(std::shared_ptr<const SweepResult> result)
{
    sweep_.reset();
    result_ = std::move(result);
    showRunning(false);
    showResult();
    emit sweepFinished(result_);
}

void SessionSweepPanel::showRunning(bool running)
{
    progressBar_->setVisible(running);
    cancelButton_->setVisible(running);
    cancelButton_->setEnabled(running);
    rerunButton_->setEnabled(!running);
    if (running) {
        progressBar_->setRange(0, 0);
        progressBar_->setValue(0);
        table_->hide();
        note_->hide();
        changes_->hide();
        changeList_->hide();
        previousButton_->hide();
        nextButton_->hide();
    }
}

void SessionSweepPanel::showResult()
{
    const bool have = result_ && result_->ok();
    table_->setVisible(have);
    changes_->setVisible(have);
    if (!result_) {
        note_->hide();
        changeList_->hide();
        previousButton_->hide();
        nextButton_->hide();
        outdatedNote_->hide();
        return;
    }
    const SweepResult& r = *result_;
    const QString name = QFileInfo(r.sourcePath).fileName();
    if (!r.ok())
        status_->setText(tr("Could not run over %1: %2").arg(name, QString::fromStdString(r.error)));
    else if (r.cancelled)
        status_->setText(tr("Cancelled after %1 of %2 frames of %3: the numbers cover those frames only.")
                             .arg(r.visited).arg(r.total).arg(name));
    else
        status_->setText(tr("%1: %2 frames in %3 s.").arg(name).arg(r.visited).arg(r.elapsedS, 0, 'f', 1));
    QStringList notes;
    if (r.ok() && r.savedIsCurrent)
        notes << tr("The current config is the saved one: nothing to compare. Change a threshold and apply again "
                    "to see which frames it changes.");
    if (!r.savedNote.empty()) notes << QString::fromStdString(r.savedNote);
    if (!r.firstFrameError.empty())
        notes << tr("%1 frame(s) could not be processed; the first: %2")
                     .arg(r.currentRow.failed)
                     .arg(QString::fromStdString(r.firstFrameError));
    note_->setText(notes.join("\n"));
    note_->setVisible(!notes.isEmpty());
    outdatedNote_->setVisible(outdated_);
    if (have) {
        fillTable(r);
        fillChanges(r);
    } else {
        changeList_->hide();
        previousButton_->hide();
        nextButton_->hide();
    }
}

void SessionSweepPanel::fillTable(const SweepResult& r)
{
    table_->clearSpans();
    const bool compare = r.hasSaved && !r.savedIsCurrent;
    table_->setColumnHidden(1, !compare);
    auto* savedHeader = new QTableWidgetItem(tr("Saved: %1").arg(QFileInfo(r.savedConfigPath).fileName()));
    savedHeader->setToolTip(r.savedConfigPath);  // which file, when several configs are about
    table_->setHorizontalHeaderItem(1, savedHeader);
    auto set = [this](int row, int column, const QString& text) { table_->setItem(row, column, new QTableWidgetItem(text)); };
    const std::pair<const std::vector<FrameOutcome>*, const EvaluationRow*> columns[] = {{&r.current, &r.currentRow},
                                                                                       {&r.saved, &r.savedRow}};
    for (int c = 0; c < 2; ++c) {
        const auto& [outcomes, row] = columns[c];
        set(FramesRow, c, framesCell(*row));
        set(FoundRow, c, foundCell(*outcomes, *row));
        set(RatioRow, c, ratioCell(*row));
        set(FalsePositiveRow, c, falsePositiveCell(*row));
        set(TimeRow, c, timeCell(*row));
    }
    table_->setRowHidden(RatioRow, !r.hasTruth);
    if (!r.hasTruth) {
        set(FalsePositiveRow, 0, tr("no truth.csv: mark ground truth to get false positives"));
        if (compare) table_->setSpan(FalsePositiveRow, 0, 1, 2);
    }
    table_->resizeRowsToContents();
    int height = table_->horizontalHeader()->height() + 2 * table_->frameWidth();
    for (int i = 0; i < RowCount; ++i)
        if (!table_->isRowHidden(i)) height += table_->rowHeight(i);
    table_->setFixedHeight(height);
}

void SessionSweepPanel::fillChanges(const SweepResult& r)
{
    changeList_->clear();
    const SessionComparison& c = r.comparison;
    const bool compare = r.hasSaved && !r.savedIsCurrent;
    if (!compare) {
        changes_->setText(tr("The slider marks the %1 frames with a ball (below the groove).").arg(detectionCount(r.current)));
    } else if (c.changed() == 0) {
        changes_->setText(tr("No frame changed against the saved config."));
    } else {
        changes_->setText(tr("%1 frames changed: %2 appeared, %3 vanished, %4 moved (marked above the slider).")
                              .arg(c.changed()).arg(c.appeared).arg(c.vanished).arg(c.moved));
        for (const FrameComparison& f : c.frames) {
            if (f.change == FrameChange::Same) continue;
            auto* item = new QListWidgetItem(changeLine(f), changeList_);
            item->setData(Qt::UserRole, f.frame);
        }
    }
    // With truth, the frames that make the numbers, to look at one by one.
    for (const auto& [frames, what] : {std::pair{&r.falsePositiveFrames, tr("false positive")}, std::pair{&r.missedFrames, tr("missed")}})
        for (int frame : *frames) {
            auto* item = new QListWidgetItem(tr("Frame %1: %2 (current config)").arg(frame).arg(what), changeList_);
            item->setData(Qt::UserRole, frame);
        }
    const bool any = compare && c.changed() > 0;
    changeList_->setVisible(any || changeList_->count() > 0);
    previousButton_->setVisible(any);
    nextButton_->setVisible(any);
}

bool SessionSweepPanel::nextChange() { return jumpToChange(+1); }
bool SessionSweepPanel::previousChange() { return jumpToChange(-1); }

bool SessionSweepPanel::jumpToChange(int step)
{
    if (!result_) return false;
    std::vector<int> frames;
    for (const FrameComparison& f : result_->comparison.frames)
        if (f.change != FrameChange::Same) frames.push_back(f.frame);
    if (frames.empty()) return false;
    std::sort(frames.begin(), frames.end());
    const int now = navigator_->current();
    int target;
    if (step > 0) {
        const auto it = std::upper_bound(frames.begin(), frames.end(), now);
        target = it != frames.end() ? *it : frames.front();
    } else {
        const auto it = std::lower_bound(frames.begin(), frames.end(), now);
        target = it != frames.begin() ? *std::prev(it) : frames.back();
    }
    navigator_->goTo(target);
    return true;
}

QString SessionSweepPanel::summaryText() const
{
    QStringList lines{status_->text()};
    if (note_->isVisible() || (!note_->text().isEmpty() && result_)) lines << note_->text();
    if (result_ && result_->ok()) {
        const bool compare = !table_->isColumnHidden(1);
        if (compare) lines << tr("Compared with %1").arg(table_->horizontalHeaderItem(1)->toolTip());
        for (int row = 0; row < RowCount; ++row) {
            if (table_->isRowHidden(row)) continue;
            QString line = table_->verticalHeaderItem(row)->text() + ": " + table_->item(row, 0)->text();
            if (compare && table_->columnSpan(row, 0) == 1) line += " | saved: " + table_->item(row, 1)->text();
            lines << line;
        }
        lines << changes_->text();
    }
    if (outdated_) lines << outdatedNote_->text();
    return lines.join('\n');
}

}  // namespace omnitune
