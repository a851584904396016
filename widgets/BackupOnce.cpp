#include "widgets/BackupOnce.h"

#include <QFileInfo>
#include <QSet>

namespace omnitune {

namespace {
QSet<QString>& backedUp()
{
    static QSet<QString> paths;  // GUI thread only
    return paths;
}
QString key(const QString& path) { return QFileInfo(path).absoluteFilePath(); }
}  // namespace

bool backedUpThisRun(const QString& path) { return backedUp().contains(key(path)); }

void rememberBackup(const QString& path) { backedUp().insert(key(path)); }

}  // namespace omnitune
