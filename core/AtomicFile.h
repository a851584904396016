#pragma once
// Saving a file so that a kill, a full disk or a second process saving at the same moment never
// leaves it half written: the new bytes go to a temporary file of a unique name beside it
// (FILE.<pid>-<n>.tmp), are flushed to disk and renamed over FILE. Saves into one folder are
// serialised between processes by a lock on the folder.
//
// The backup rule (the same for the window and every tool): FILE.bak is FILE as it was before
// OmniTune first replaced it. A save makes FILE.bak only when there is none, as a hard link to
// the old file (never a copy being written, so it cannot be cut short); an existing FILE.bak is
// never touched. Delete it to take a fresh backup at the next save.
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

// A file's new bytes, written and flushed to a temporary beside it until commit() renames them
// over the file. An uncommitted temporary is removed when the object goes.
class StagedFile {
public:
    StagedFile(std::string path, const std::string& bytes);
    ~StagedFile();
    StagedFile(const StagedFile&) = delete;
    StagedFile& operator=(const StagedFile&) = delete;

    // Set when the temporary could not be written; commit() then does nothing.
    const std::optional<std::string>& error() const { return error_; }
    const std::string& path() const { return path_; }

    // Keeps the backup when asked (see the rule above), then renames the temporary over path().
    std::optional<std::string> commit(bool keepBackup);

private:
    std::string path_;
    std::string temp_;  // empty once renamed or removed
    std::optional<std::string> error_;
};

// Holds the save lock of the folder holding `file` while it lives. Another process holding it
// is waited for a few seconds, then error() says so (nothing may be written then).
class FolderSaveLock {
public:
    explicit FolderSaveLock(const std::string& file);
    ~FolderSaveLock();
    FolderSaveLock(const FolderSaveLock&) = delete;
    FolderSaveLock& operator=(const FolderSaveLock&) = delete;

    const std::optional<std::string>& error() const { return error_; }

private:
    int fd_ = -1;
    std::optional<std::string> error_;
};

// Writes `bytes` to `path` atomically under the folder's lock, keeping the backup when
// `keepBackup` (see the rule above). On failure returns a message naming the file and the
// system's reason, and `path` is as it was.
std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes,
                                               bool keepBackup = true);

}  // namespace omnitune
