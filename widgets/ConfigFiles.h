#pragma once
// The config document's files as the window handles them: loading (a dialog names the
// fault, the notice bar lists the warnings), saving and Save As, asking before unsaved edits
// are lost, and which config a newly opened source gets. A source without a config of its
// own keeps the values on screen; when they are the previous session's own config.yml they
// are unlinked from that file, so Save never writes one session's tuning into another's
// folder unasked (Save As then proposes a config.yml beside the new source).
#include <QObject>
#include <QString>

class QWidget;

namespace omnitune {

class ConfigDocument;
class NoticeBar;

class ConfigFiles : public QObject {
    Q_OBJECT
public:
    // `window`: the parent of the dialogs.
    ConfigFiles(ConfigDocument* doc, NoticeBar* notices, QWidget* window);

    // Loads `path` (opened by hand). False on failure (said in a dialog; nothing changes).
    bool open(const QString& path);
    // A session's own config.yml, which keepFor() unlinks when the next source has none.
    bool openSessionConfig(const QString& path);
    // The source `name` (at `path`; `sessionFolder` when it is a session) has no config.
    void keepFor(const QString& name, const QString& path, const QString& sessionFolder);
    bool save();    // Save As when the config has no file
    bool saveAs();
    // Asks `question` (Save / Discard / Cancel) when there are unsaved changes. False:
    // cancelled or the save failed. `discardNow`: Discard also drops the edits at once.
    bool maybeSave(const QString& question, bool discardNow);
    // File > Open config: asks about unsaved changes, then a file dialog. The path opened, or empty.
    QString choose();
    // For the title bar: the file name, or what a config without a file is.
    QString name() const;
    // The built-in defaults, never loaded from or saved to a file: adapting them to a new
    // camera replaces nothing of the user's.
    bool showsBuiltInDefaults() const;

signals:
    void message(const QString& text);  // for the status bar

private:
    ConfigDocument* doc_;
    NoticeBar* notices_;
    QWidget* window_;
    QString sessionConfigPath_;    // the config.yml the open session brought, while it is the one shown
    QString suggestedPath_;        // where Save As proposes to put a config that has no file
    QString origin_;               // names a config without a file
    bool builtInDefaults_ = true;  // no config was loaded or saved since the window opened
};

}  // namespace omnitune
