#include "widgets/TruthDocument.h"

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

namespace {

// truth.csv.bak is the file as it was before OmniTune first saved it (core/AtomicFile.h): every
// save asks for it, and the writer leaves an existing one alone.
constexpr bool kKeepBackup = true;

std::optional<QString> toQt(const std::optional<std::string>& err)
{
    if (err) return QString::fromStdString(*err);
    return std::nullopt;
}

}  // namespace

std::optional<QString> TruthDocument::set(const TruthRow& row)
{
    bool changedRows = false;
    const auto err = store_.set(row, kKeepBackup, &changedRows);
    if (changedRows) emit changed(row.frame);
    return toQt(err);
}

std::optional<QString> TruthDocument::remove(int frame)
{
    bool changedRows = false;
    const auto err = store_.remove(frame, kKeepBackup, &changedRows);
    if (changedRows) emit changed(frame);
    return toQt(err);
}

std::optional<QString> TruthDocument::save()
{
    if (!isOpen()) return std::nullopt;
    return toQt(store_.save(kKeepBackup));
}

}  // namespace omnitune
