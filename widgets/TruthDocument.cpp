#include "widgets/TruthDocument.h"

#include "widgets/BackupOnce.h"

namespace omnitune {

TruthDocument::TruthDocument(QObject* parent) : QObject(parent) {}

std::optional<QString> TruthDocument::open(const QString& sessionDir, QStringList* warnings, const TruthLimits& limits)
{
    std::vector<std::string> found;
    const auto err = store_.open(sessionDir.toStdString(), &found, limits);
    if (warnings)
        for (const auto& w : found) *warnings << QString::fromStdString(w);
    emit changed(-1);
    if (err) return QString::fromStdString(*err);
    return std::nullopt;
}

void TruthDocument::close(const QString& why)
{
    store_.close(why.toStdString());
    emit changed(-1);
}

// A reopened session keeps its first backup: only the first save of this run writes one.
bool TruthDocument::keepBackup() const { return !backedUpThisRun(path()); }

std::optional<QString> TruthDocument::saved(const std::optional<std::string>& err, bool wrote)
{
    if (err) return QString::fromStdString(*err);
    if (wrote) rememberBackup(path());
    return std::nullopt;
}

std::optional<QString> TruthDocument::set(const TruthRow& row)
{
    bool changedRows = false;
    const auto err = store_.set(row, keepBackup(), &changedRows);
    if (changedRows) emit changed(row.frame);
    return saved(err, changedRows);
}

std::optional<QString> TruthDocument::remove(int frame)
{
    bool changedRows = false;
    const auto err = store_.remove(frame, keepBackup(), &changedRows);
    if (changedRows) emit changed(frame);
    return saved(err, changedRows);
}

std::optional<QString> TruthDocument::save()
{
    if (!isOpen()) return std::nullopt;
    return saved(store_.save(keepBackup()), true);
}

}  // namespace omnitune
