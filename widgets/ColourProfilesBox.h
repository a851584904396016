#pragma once
// The "Venue profiles" group of the Colours tab: the colour calibrations saved by name beside
// the config (colour-profiles/NAME.yml, calib/colour/ColourProfile.h), and Save as, Load (the
// profile's colours replace the config's, one undo step), Delete and Compare (ColourDiffView:
// the profile against the config's colours on the frame on screen). A profile file that does not
// load is listed with its fault, and Load or Compare on it says which file and what is wrong.
#include "widgets/PipelineRunner.h"

#include <QGroupBox>

#include <memory>
#include <optional>

class QLabel;
class QListWidget;

namespace omnitune {

class ColourDiffView;
class ConfigDocument;

class ColourProfilesBox : public QGroupBox {
    Q_OBJECT
public:
    // `doc` must outlive the box.
    explicit ColourProfilesBox(ConfigDocument* doc, QWidget* parent = nullptr);

    void setRun(std::shared_ptr<const PipelineRun> run) { run_ = std::move(run); }

    // The folder of the document's profiles; empty while the config has no file.
    QString folder() const;
    // Rereads the folder.
    void refreshList();

    // The edits behind the buttons (without their dialogs); the reason when refused.
    std::optional<QString> saveProfile(const QString& name);
    std::optional<QString> loadProfile(const QString& path);
    std::optional<QString> deleteProfile(const QString& path);
    // Opens the comparison of the profile (right) with the config's colours (left), or says why not.
    std::optional<QString> compareProfile(const QString& path);

    QListWidget* list() const { return list_; }
    // The comparison open last (null before the first).
    ColourDiffView* diffView() const { return diff_; }
    // The selected row's profile file (empty: none).
    QString selectedPath() const;

signals:
    void message(const QString& text);  // for the status bar

private:
    void askSave();

    ConfigDocument* doc_;
    QListWidget* list_;
    QLabel* hint_;
    std::shared_ptr<const PipelineRun> run_;
    ColourDiffView* diff_ = nullptr;
};

}  // namespace omnitune
