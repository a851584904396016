#pragma once
// The config the workbench edits: one core::Config, the window's undo stack (key changes, and
// the ground-truth marks that share it), and where it is saved. Every editor changes it through setValue() (one undoable command per change), so
// the GUI never keeps a parallel copy. Loading and saving go through the core's parser and
// atomic writer; a failed load leaves the current config untouched.
#include "core/Config.h"
#include "core/ConfigSchema.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <optional>

namespace omnitune {

class ConfigDocument : public QObject {
    Q_OBJECT
public:
    explicit ConfigDocument(QObject* parent = nullptr);

    const Config& config() const { return config_; }
    // The window's one undo stack. Other commands (truth marks) may share it: the config is
    // dirty when it differs from what was last loaded or saved, not when the stack is unclean.
    // Setting the stack clean marks the current config as saved.
    QUndoStack* undoStack() { return &undo_; }
    QString path() const { return path_; }
    bool isDirty() const { return dirty_; }

    // Sets one schema key; a change that would make the config invalid (checkConfig) is
    // refused and its message returned. No-op (and no undo entry) when the value is the same.
    std::optional<QString> setValue(const QString& key, const ConfigValue& value);
    ConfigValue value(const QString& key) const;
    // Replaces the whole config (keys and mask) as one undo step named `text` ("Fit mirror rim"),
    // checked as a whole; refused with the first problem's message.
    std::optional<QString> replaceConfig(const Config& next, const QString& text);

    // Replaces the config with the file's; on error returns the message (file, key, fault) and
    // changes nothing. Warnings (missing keys, ...) are returned through `warnings`.
    std::optional<QString> load(const QString& path, QStringList* warnings = nullptr);
    // Atomic save with backup (core::saveConfig); marks the document clean.
    std::optional<QString> save();
    std::optional<QString> saveAs(const QString& path);
    // Back to the last loaded or saved state (clears the undo stack).
    std::optional<QString> revert();
    // Back to the last loaded or saved values without reading the file (clears the undo stack).
    void discardChanges();
    // A config that did not come from a file (defaults, a session's own): no path, clean.
    void reset(const Config& config, const QString& path = {});

    // Applied by the undo commands; not for editors.
    void applyValue(const QString& key, const ConfigValue& value);
    void applyConfig(const Config& config);

signals:
    void changed(const QString& key);  // empty key: everything may have changed
    void dirtyChanged(bool dirty);
    void pathChanged(const QString& path);

private:
    void updateDirty();
    void markSaved();

    Config config_;
    Config saved_;  // as last loaded or saved
    bool dirty_ = false;
    QString path_;
    QUndoStack undo_;
};

}  // namespace omnitune
