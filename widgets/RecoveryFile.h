#pragma once
// Crash recovery for the config the window edits: while the document has unsaved edits they
// are kept in a recovery file, written atomically a few seconds after the last edit and at
// least once a minute while edits keep coming, in a per-user folder and named after the
// config file's path. Saving, reverting, undoing back to the saved state or closing without
// keeping the edits removes it; a file left behind means a run ended without either, and the
// next time that config is opened RecoveryOffer offers it back (docs/user-guide.md).
#include "calib/config/ConfigDiff.h"
#include "core/Config.h"

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

class QLockFile;

namespace omnitune {

class ConfigDocument;

// What a recovery file left by an earlier run holds, compared with the config as saved.
struct RecoveredEdits {
    QString file;                       // the recovery file
    QDateTime written;                  // when the earlier run last wrote it
    std::vector<ConfigChange> changes;  // saved value -> recovered value, schema order
    QString error;                      // non-empty: the file cannot be read (then kept, never used)
};

class RecoveryFile : public QObject {
    Q_OBJECT
public:
    static constexpr int kDebounceMs = 2000;  // written this long after the last edit...
    static constexpr int kMaxAgeMs = 60000;   // ...and at least this often while edits keep coming

    explicit RecoveryFile(ConfigDocument* doc, QObject* parent = nullptr);
    ~RecoveryFile() override;

    // $OMNITUNE_RECOVERY_DIR when set (tests), else "recovery" in the user's application data
    // folder (~/.local/share/OmniTune/recovery on Linux).
    static QString directory();
    // The recovery file of a config file: its name and a hash of its absolute path, so two
    // configs named config.yml in different sessions never share one. A config that has no
    // file yet (the defaults) has "untitled.yml".
    static QString fileFor(const QString& configPath);

    void setIntervals(int debounceMs, int maxAgeMs);  // tests

    // A recovery file for `configPath` left by a run that ended with unsaved edits, compared with
    // `saved` (the config as loaded from that path). Nothing when there is none, when this run
    // wrote it, when another running window owns it (its lock), or when it holds no difference
    // (then it is removed).
    std::optional<RecoveredEdits> pending(const QString& configPath, const Config& saved);
    // Applies the recovered values as one undo step (Ctrl+Z takes it back) and takes the file
    // over as this run's. Returns the changes the document refused, with the reason.
    QStringList restore(const RecoveredEdits& edits);
    // Removes a recovery file the user declined.
    void drop(const RecoveredEdits& edits);

    // Writes the document's unsaved edits now; the fault when the file cannot be written.
    std::optional<QString> writeNow();
    // Removes the file this run wrote (the edits were saved, reverted or deliberately dropped).
    void discard();
    QString writtenFile() const { return written_; }

signals:
    void writeFailed(const QString& message);  // once per distinct failure; the edits stay in memory

private:
    void onEdited();
    QString fail(const QString& why);  // reports a write failure once; returns it
    bool lockedByOther(const QString& file);  // locks `file` for this run unless a live window has it

    ConfigDocument* doc_;
    QTimer debounce_;
    QTimer maxAge_;  // runs from the first edit not yet written
    QString written_;  // the recovery file this run owns (wrote or took over); empty: none
    // "<file>.lock" while this run owns a recovery file, so that a second window on the same
    // config does not offer live edits as a crash's; a killed run's lock is stale (dead PID).
    std::unique_ptr<QLockFile> lock_;
    QString locked_;  // the recovery file lock_ is for
    QString lastFailure_;  // reported already; cleared by a successful write
};

}  // namespace omnitune
