#pragma once
// File > Save as session... (issue 11): the open image folder, glob or video becomes a session
// folder (calib/session/SessionExport.h) so that it can be marked and evaluated. Asks for a
// new folder, writes the frames with a progress dialog that can cancel, and says what went
// wrong; the window then opens the folder. The writing itself lives in calib/.
#include "core/Config.h"

#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace omnitune {

class SaveAsSession : public QObject {
    Q_OBJECT
public:
    explicit SaveAsSession(QWidget* parent);

    // Asks where the session goes (a folder that does not exist yet, or an empty one), given a
    // suggestion; empty: cancelled. A file dialog by default; tests answer it themselves.
    using FolderAsker = std::function<QString(const QString& suggested)>;
    void setFolderAsker(FolderAsker ask) { ask_ = std::move(ask); }

    // Saves `sourcePath` with `config` as its config.yml. Returns the new session's folder, or
    // empty when cancelled or failed (failures are shown in a message box).
    QString save(const QString& sourcePath, const Config& config);

signals:
    void message(const QString& text);  // what was saved, for the status bar

private:
    QWidget* parentWidget_;
    FolderAsker ask_;
};

}  // namespace omnitune
