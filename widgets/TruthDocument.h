#pragma once
// The ground truth of the open session (its truth.csv) while someone marks it in the window.
// Every change is written at once, atomically, so a crash or a closed laptop loses no mark;
// the file as it was when the program first opened it is kept as truth.csv.bak (written on
// the first change only, so later saves, and reopening the session, never overwrite it).
#include "calib/session/TruthCsv.h"

#include <QObject>
#include <QString>

#include <map>
#include <optional>

namespace omnitune {

class TruthDocument : public QObject {
    Q_OBJECT
public:
    explicit TruthDocument(QObject* parent = nullptr);

    // Reads `sessionDir`/truth.csv (a missing file is an empty truth). Returns the reason
    // marking is not possible (an unreadable file, or one whose header cannot be used: saving
    // over it would lose rows), and leaves the document closed then. Warnings name the
    // skipped rows, which a save would drop (the .bak keeps them).
    std::optional<QString> open(const QString& sessionDir, QStringList* warnings = nullptr);
    // `why`: what to tell someone who tries to mark while no truth is open.
    void close(const QString& why = {});
    bool isOpen() const { return !path_.isEmpty(); }
    QString closedReason() const { return closedReason_; }
    QString path() const { return path_; }

    const std::map<int, TruthRow>& rows() const { return rows_; }
    const TruthRow* row(int frame) const;

    // Sets or replaces the row of `row.frame` and saves; on a failed save the row is kept in
    // memory (and saved with the next change) and the message names the file and the fault.
    std::optional<QString> set(const TruthRow& row);
    std::optional<QString> remove(int frame);
    // Marks a failed save kept only in memory; save() tries again.
    bool hasUnsavedMarks() const { return unsaved_; }
    std::optional<QString> save();

signals:
    void changed(int frame);  // -1: everything (opened or closed)

private:
    QString path_;
    std::map<int, TruthRow> rows_;
    bool unsaved_ = false;
    QString closedReason_;
};

}  // namespace omnitune
