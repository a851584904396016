#pragma once
// The sources and configs opened lately, newest first, kept across runs in QSettings, and the
// "Open recent" menu that shows them. At the venue the same two or three sessions are
// reopened all day.
#include <QObject>
#include <QStringList>

class QMenu;

namespace omnitune {

class RecentFiles : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxEntries = 8;

    // `settingsKey` names the list in QSettings (the application's default settings).
    RecentFiles(const QString& settingsKey, QMenu* menu, QObject* parent = nullptr);

    QStringList paths() const { return paths_; }
    // Moves `path` (made absolute) to the top and saves the list.
    void add(const QString& path);

signals:
    void chosen(const QString& path);

private:
    void rebuildMenu();

    QString key_;
    QMenu* menu_;
    QStringList paths_;
};

}  // namespace omnitune
