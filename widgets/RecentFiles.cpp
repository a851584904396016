#include "RecentFiles.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace omnitune {

RecentFiles::RecentFiles(const QString& settingsKey, QMenu* menu, QObject* parent)
    : QObject(parent), key_(settingsKey), menu_(menu), paths_(QSettings().value(settingsKey).toStringList())
{
    while (paths_.size() > kMaxEntries) paths_.removeLast();
    rebuildMenu();
}

void RecentFiles::add(const QString& path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    paths_.removeAll(absolute);
    paths_.prepend(absolute);
    while (paths_.size() > kMaxEntries) paths_.removeLast();
    QSettings().setValue(key_, paths_);
    rebuildMenu();
}

void RecentFiles::rebuildMenu()
{
    menu_->clear();
    for (int i = 0; i < paths_.size(); ++i) {
        const QString path = paths_[i];
        // "&1 demo  (/home/team/sessions/demo)": the name to find, the folder to tell apart.
        QAction* a = menu_->addAction(tr("&%1 %2  (%3)").arg(i + 1).arg(QFileInfo(path).fileName(), QFileInfo(path).path()));
        a->setEnabled(QFileInfo::exists(path));
        connect(a, &QAction::triggered, this, [this, path] { emit chosen(path); });
    }
    menu_->setEnabled(!paths_.isEmpty());
}

}  // namespace omnitune
