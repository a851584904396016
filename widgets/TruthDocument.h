#pragma once
// The open session's ground truth in the window: calib's TruthStore (rows, opening, atomic
// saves) with Qt strings and a signal per change. The file as it was before this program
// first saved it is kept as truth.csv.bak (core/AtomicFile.h).
#include "calib/session/TruthStore.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <map>
#include <optional>

namespace omnitune {

class TruthDocument : public QObject {
    Q_OBJECT
public:
    explicit TruthDocument(QObject* parent = nullptr);

    // Reads `sessionDir`/truth.csv (TruthStore::open); returns why marking is not possible.
    std::optional<QString> open(const QString& sessionDir, QStringList* warnings = nullptr, const TruthLimits& limits = {});
    // `why`: what to tell someone who tries to mark while no truth is open.
    void close(const QString& why = {});
    bool isOpen() const { return store_.isOpen(); }
    QString closedReason() const { return QString::fromStdString(store_.closedReason()); }
    QString path() const { return QString::fromStdString(store_.path()); }

    const std::map<int, TruthRow>& rows() const { return store_.rows(); }
    const TruthRow* row(int frame) const { return store_.row(frame); }

    // Sets or replaces the row of `row.frame` and saves; on a failed save the row is kept in
    // memory (and saved with the next change) and the message names the file and the fault.
    std::optional<QString> set(const TruthRow& row);
    std::optional<QString> remove(int frame);
    // Marks a failed save kept only in memory; save() tries again.
    bool hasUnsavedMarks() const { return store_.hasUnsavedRows(); }
    std::optional<QString> save();

signals:
    void changed(int frame);  // -1: everything (opened or closed)

private:
    TruthStore store_;
};

}  // namespace omnitune
