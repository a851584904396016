#include "calib/session/TruthStore.h"

#include "core/RegularFile.h"

#include "calib/session/Session.h"
#include "core/ConfigWriter.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace omnitune {

std::string TruthStore::defaultClosedReason()
{
    return "ground truth is kept in a session folder's truth.csv: open a session to mark it";
}

std::optional<std::string> TruthStore::open(const std::string& sessionDir, std::vector<std::string>* warnings,
                                            const TruthLimits& limits)
{
    close();
    const std::string path = (std::filesystem::path(sessionDir) / std::string(kSessionTruthFile)).string();
    std::map<int, TruthRow> rows;
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) {
        if (const auto notRegular = checkRegularFile(path)) {  // a FIFO would block the window for good
            close(path + ": " + *notRegular + "; ground truth cannot be marked");
            return closedReason_;
        }
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        if (!in || !(text << in.rdbuf())) {
            close(path + ": cannot be read; ground truth cannot be marked");
            return closedReason_;
        }
        const TruthParse parsed = parseTruthCsv(text.str(), path, limits);
        if (!parsed.ok()) {
            close(parsed.error->toString() + "; fix or remove the file to mark ground truth");
            return closedReason_;
        }
        if (warnings)
            for (const SessionIssue& w : parsed.warnings)
                warnings->push_back(w.toString() + " (dropped when a mark is saved: fix the row first to keep it)");
        rows = parsed.rows;
    }
    path_ = path;
    rows_ = std::move(rows);
    closedReason_.clear();
    return std::nullopt;
}

void TruthStore::close(const std::string& why)
{
    closedReason_ = why.empty() ? defaultClosedReason() : why;
    path_.clear();
    rows_.clear();
    unsaved_ = false;
}

const TruthRow* TruthStore::row(int frame) const
{
    const auto it = rows_.find(frame);
    return it == rows_.end() ? nullptr : &it->second;
}

std::optional<std::string> TruthStore::set(const TruthRow& row, bool keepBackup, bool* changed)
{
    if (changed) *changed = false;
    if (!isOpen()) return closedReason_;
    rows_[row.frame] = row;
    if (changed) *changed = true;
    return save(keepBackup);
}

std::optional<std::string> TruthStore::remove(int frame, bool keepBackup, bool* changed)
{
    if (changed) *changed = false;
    if (!isOpen()) return closedReason_;
    if (rows_.erase(frame) == 0) return std::nullopt;
    if (changed) *changed = true;
    return save(keepBackup);
}

std::optional<std::string> TruthStore::save(bool keepBackup)
{
    if (!isOpen()) return std::nullopt;
    if (auto err = writeFileAtomically(path_, serializeTruthCsv(rows_), keepBackup)) {
        unsaved_ = true;
        return *err + " (the marks are kept in memory; the next mark tries again)";
    }
    unsaved_ = false;
    return std::nullopt;
}

}  // namespace omnitune
