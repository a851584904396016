#include "widgets/TruthDocument.h"

#include "core/ConfigWriter.h"
#include "core/RegularFile.h"
#include "calib/session/Session.h"

#include <QDir>
#include <QFile>

namespace omnitune {

TruthDocument::TruthDocument(QObject* parent) : QObject(parent) {}

std::optional<QString> TruthDocument::open(const QString& sessionDir, QStringList* warnings)
{
    close();
    const QString path = QDir(sessionDir).filePath(QString::fromUtf8(kSessionTruthFile.data(), int(kSessionTruthFile.size())));
    std::map<int, TruthRow> rows;
    QFile file(path);
    if (file.exists()) {
        if (const auto notRegular = checkRegularFile(path.toStdString())) {  // a FIFO would block the window for good
            close(tr("%1: %2; ground truth cannot be marked").arg(path, QString::fromStdString(*notRegular)));
            return closedReason_;
        }
        if (!file.open(QIODevice::ReadOnly)) {
            close(tr("%1: cannot be read (%2); ground truth cannot be marked").arg(path, file.errorString()));
            return closedReason_;
        }
        const TruthParse parsed = parseTruthCsv(file.readAll().toStdString(), path.toStdString());
        if (!parsed.ok()) {
            close(tr("%1; fix or remove the file to mark ground truth").arg(QString::fromStdString(parsed.error->toString())));
            return closedReason_;
        }
        if (warnings)
            for (const SessionIssue& w : parsed.warnings)
                *warnings << tr("%1 (dropped when a mark is saved; truth.csv.bak keeps it)").arg(QString::fromStdString(w.toString()));
        rows = parsed.rows;
    }
    path_ = path;
    rows_ = std::move(rows);
    closedReason_.clear();
    emit changed(-1);
    return std::nullopt;
}

void TruthDocument::close(const QString& why)
{
    closedReason_ = why.isEmpty() ? tr("ground truth is kept in a session folder's truth.csv: open a session to mark it") : why;
    path_.clear();
    rows_.clear();
    unsaved_ = false;
    emit changed(-1);
}

const TruthRow* TruthDocument::row(int frame) const
{
    const auto it = rows_.find(frame);
    return it == rows_.end() ? nullptr : &it->second;
}

std::optional<QString> TruthDocument::set(const TruthRow& row)
{
    if (!isOpen()) return closedReason_;
    rows_[row.frame] = row;
    emit changed(row.frame);
    return save();
}

std::optional<QString> TruthDocument::remove(int frame)
{
    if (!isOpen()) return closedReason_;
    if (rows_.erase(frame) == 0) return std::nullopt;
    emit changed(frame);
    return save();
}

std::optional<QString> TruthDocument::save()
{
    if (!isOpen()) return std::nullopt;
    if (const auto err = writeFileAtomically(path_.toStdString(), serializeTruthCsv(rows_))) {
        unsaved_ = true;
        return tr("%1 (the marks are kept in memory; the next mark tries again)").arg(QString::fromStdString(*err));
    }
    unsaved_ = false;
    return std::nullopt;
}

}  // namespace omnitune
