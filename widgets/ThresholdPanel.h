#pragma once
// The detector's thresholds (edges, both Hough paths, validation, algorithm) as a scrollable
// column of editors built from the config schema: one group per section, one row per key, with
// the schema's range, unit and meaning (as tooltip). Edits go through ConfigDocument::setValue;
// a refused edit puts the editor back and shows why. Document changes (undo, redo, load) update
// the editors without editing again, except one the user is typing in: it follows the document
// when it loses focus. A search box on top filters the rows by key, name or group as you type,
// so that a group far down (validation) is a few letters away on a small screen.
#include "core/ConfigSchema.h"

#include <QHash>
#include <QList>
#include <QSet>
#include <QString>
#include <QWidget>

class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;

namespace omnitune {

class ConfigDocument;

class ThresholdPanel : public QWidget {
    Q_OBJECT
public:
    // `doc` must outlive the panel.
    explicit ThresholdPanel(ConfigDocument* doc, QWidget* parent = nullptr);
    ~ThresholdPanel() override;

    // The config sections shown, in order ("edges", "hough", ...).
    static QStringList sections();

    // The editor of a schema key ("edges.canny_low"), nullptr when the panel has none. Editors are
    // QSpinBox, QDoubleSpinBox, QCheckBox, QComboBox or QLineEdit; their objectName is the key.
    QWidget* editorFor(const QString& key) const;
    // The message of the last refused edit; empty after a successful one.
    QString statusMessage() const;
    // Shows only the rows whose key, name or group contains every word of `text` (case-
    // insensitive); empty shows all. The search box calls it as the user types.
    void setFilter(const QString& text);
    QLineEdit* searchBox() const { return search_; }

signals:
    void editRefused(const QString& message);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void addEditor(const ConfigKey& key, QFormLayout* form, QGroupBox* group, const QString& groupTitle);
    // Edits the document; false (editor reverted or marked, message shown) when refused.
    bool apply(const QString& key, const ConfigValue& value);
    void applyListText(const QString& key);
    void refuse(const QString& message);
    void onDocumentChanged(const QString& key);
    void syncEditor(const QString& key);
    void setInvalid(QWidget* editor, bool invalid);
    // validation.ball_hint_class's choices: none and every class that is not a field class.
    void fillClassNames(QComboBox* combo, const std::string& current);
    void setStatus(const QString& message);

    ConfigDocument* doc_;
    QHash<QString, QWidget*> editors_;
    QList<QLabel*> labels_;
    // What the search box looks through, one entry per row.
    struct Row {
        QLabel* label;
        QWidget* editor;
        QGroupBox* group;
        QString text;  // key, plain label and group title, lower case
    };
    QList<Row> rows_;
    QLineEdit* search_ = nullptr;
    QLabel* noMatch_ = nullptr;
    QSet<QString> typing_;  // keys whose editor holds text the user has typed but not committed
    QLabel* status_ = nullptr;
};

}  // namespace omnitune
