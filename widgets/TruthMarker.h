#pragma once
// Ground-truth marking on the panes: in marking mode a click on the ball's centre marks it
// with the radius the ball model expects there, a drag from the centre sets the radius by
// hand, one key accepts the detector's result (ball or no ball) as truth, one marks "no ball",
// and each of these moves on to the next frame, so a tour of hundreds of frames is a click or
// a key per frame. The marks go to the session's truth.csv through TruthDocument, each as a
// command on the window's undo stack (Ctrl+Z restores the frame's previous row and saves).
// What it draws and describes is the truth of the frame whose image the panes show (the
// latest run), never the frame the slider asks for next.
#include "widgets/Overlay.h"
#include "widgets/PipelineRunner.h"
#include "calib/session/TruthCsv.h"

#include <QObject>
#include <QPointF>

#include <functional>
#include <memory>
#include <optional>

class QAction;
class QMenu;
class QUndoStack;

namespace omnitune {

class PipelineView;
class TruthDocument;

class TruthMarker : public QObject {
    Q_OBJECT
public:
    // A drag shorter than this (image px) is a click: the model's radius is used.
    static constexpr double kClickRadiusPx = 1.5;

    // Marks are pushed on `undo` (the window's one stack, shared with the config's edits).
    TruthMarker(TruthDocument* truth, PipelineView* view, QUndoStack* undo, QObject* parent = nullptr);

    // A new source: marking off, nothing on screen yet.
    void reset(int frameCount);
    void setFrame(int frame);  // the frame asked for: marks go to it once its run is shown
    // The run the panes show (null: none): its frame's truth is drawn, its config measures
    // marked balls, its detection is what "accept" takes.
    void setRun(std::shared_ptr<const PipelineRun> run);
    int shownFrame() const { return run_ ? run_->frameIndex : -1; }

    bool isMarking() const { return marking_; }
    // Refused (and said) while no truth is open; the menu's check mark follows.
    void setMarking(bool on);
    // Asks whether to keep a mark whose radius is far outside the ball model (TruthMarkRules);
    // a message box by default. True: keep it.
    void setConfirm(std::function<bool(const QString& question)> confirm) { confirm_ = std::move(confirm); }
    void setAdvanceAfterMark(bool on) { advance_ = on; }
    bool advancesAfterMark() const { return advance_; }

    // Each returns nothing on success, or why not (for the status bar).
    // `radius` <= 0: the ball model's expected radius at the centre's distance.
    std::optional<QString> markBall(QPointF centre, double radius);
    std::optional<QString> acceptDetection();
    std::optional<QString> markNoBall();
    std::optional<QString> clearMark();

    // The first frame after `from` (wrapping round) without a mark; -1 when all are marked.
    int nextUnmarked(int from) const;
    // "truth: ball 2.31 m away | 40 of 120 frames marked", or empty with no truth open.
    QString describe() const;

    // The Truth menu: marking mode (T), "next frame after each mark", and the marking keys
    // (A, N, Delete, U), which act only in marking mode so a stray key never writes truth.
    void fillMenu(QMenu* menu);

signals:
    void advanceRequested();          // a mark was made with "advance after marking" on
    void frameRequested(int frame);   // "next unmarked frame"
    void message(const QString& text);  // a refusal, a mark, an undo or a failed save, for the status bar
    void described(const QString& text);  // describe() changed
    void markingChanged(bool on);
    void markingRefused();  // marking mode was asked for while no truth is open (after message())

private:
    void onPressed(QPointF p);
    void onDragged(QPointF p);
    void onReleased(QPointF p);
    std::optional<QString> commit(TruthRow row);
    friend class TruthMarkCommand;
    // Sets (or, without a row, removes) `frame`'s row of the truth file at `path`; undo/redo.
    std::optional<QString> apply(const QString& path, int frame, const std::optional<TruthRow>& row);
    void refresh();
    bool runIsCurrent() const;
    std::optional<QString> notOnScreen() const;
    static QString rowText(const TruthRow& row);  // "ball at (320, 65) px, 2.01 m away" / "no ball"

    TruthDocument* truth_;
    PipelineView* view_;
    QUndoStack* undo_;
    std::function<bool(const QString&)> confirm_;
    QAction* markingAction_ = nullptr;
    QList<QAction*> markingKeys_;  // enabled only in marking mode
    QString refusal_;  // why marking mode was refused, shown until the source changes
    std::shared_ptr<const PipelineRun> run_;
    int frame_ = -1;
    int count_ = 0;
    bool marking_ = false;
    bool advance_ = true;
    bool dragging_ = false;
    QPointF dragCentre_;
    double dragRadius_ = 0.0;
};

}  // namespace omnitune
