#include "widgets/RecentFiles.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QRegularExpression>
#include <QSettings>
#include <QTimer>

namespace omnitune {

RecentFiles::RecentFiles(const QString& settingsKey, QMenu* menu, QObject* parent)
    : QObject(parent), key_(settingsKey), menu_(menu), paths_(QSettings().value(settingsKey).toStringList())
{
    while (paths_.size() > kMaxEntries) paths_.removeLast();
    rebuildMenu();
    connect(menu_, &QMenu::aboutToShow, this, &RecentFiles::rebuildMenu);  // files vanish between uses
}

void RecentFiles::add(const QString& path)
{
    const QString absolute = QDir::cleanPath(QFileInfo(path).absoluteFilePath());
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
        // A pattern (run/*.png) is no file of its own; the source says if nothing matches.
        a->setEnabled(QFileInfo::exists(path) || path.contains(QRegularExpression("[*?\\[]")));
        // Later: opening rebuilds this menu, which must not delete the action still signalling.
        connect(a, &QAction::triggered, this, [this, path] { QTimer::singleShot(0, this, [this, path] { emit chosen(path); }); });
    }
    menu_->setEnabled(!paths_.isEmpty());
}

}  // namespace omnitune
