#pragma once
// The ground truth of one session folder (its truth.csv) while someone marks it: the rows by
// frame, opening (a missing file is an empty truth; a file whose header cannot be used is
// refused, since saving over it would lose rows) and saving the whole file atomically after
// every change, so a crash loses no mark. Qt-free; widgets/TruthDocument adds the signals.
// Whether a save keeps a .bak is the caller's policy (`keepBackup`).
#include "calib/session/TruthCsv.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

class TruthStore {
public:
    // Reads `sessionDir`/truth.csv. Returns why marking is not possible (unreadable file,
    // unusable header) and stays closed then. `warnings` name the rows a save would drop;
    // `limits` (the session's frame size) refuse rows no frame can hold, as the tools do.
    std::optional<std::string> open(const std::string& sessionDir, std::vector<std::string>* warnings = nullptr,
                                    const TruthLimits& limits = {});
    // `why`: what to tell someone who tries to mark while no truth is open (empty: a default).
    void close(const std::string& why = {});
    bool isOpen() const { return !path_.empty(); }
    const std::string& closedReason() const { return closedReason_; }
    const std::string& path() const { return path_; }

    const std::map<int, TruthRow>& rows() const { return rows_; }
    const TruthRow* row(int frame) const;

    // Sets (replaces) or removes a frame's row and saves. On a failed save the change is kept
    // in memory (hasUnsavedRows) and the message names the file and the fault. `changed`
    // tells whether the rows changed (false when refused or when there was nothing to remove).
    std::optional<std::string> set(const TruthRow& row, bool keepBackup, bool* changed = nullptr);
    std::optional<std::string> remove(int frame, bool keepBackup, bool* changed = nullptr);
    bool hasUnsavedRows() const { return unsaved_; }
    std::optional<std::string> save(bool keepBackup);

private:
    std::string path_;
    std::map<int, TruthRow> rows_;
    bool unsaved_ = false;
    std::string closedReason_ = defaultClosedReason();

    static std::string defaultClosedReason();
};

}  // namespace omnitune
