#include "widgets/ColourProfilesBox.h"

#include "calib/colour/ColourProfile.h"
#include "widgets/ColourDiffView.h"
#include "widgets/ColourSwatch.h"
#include "widgets/ConfigDocument.h"

#include <QFileInfo>
#include <QLineEdit>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

#include <filesystem>
#include <functional>
#include <system_error>

namespace omnitune {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

ColourProfilesBox::ColourProfilesBox(ConfigDocument* doc, QWidget* parent)
    : QGroupBox(tr("Venue profiles"), parent), doc_(doc), list_(new QListWidget), hint_(new QLabel)
{
    setObjectName("colourProfiles");
    auto* layout = new QVBoxLayout(this);
    list_->setObjectName("profileList");
    list_->setMaximumHeight(110);
    list_->setToolTip(tr("Colour calibrations saved by name in colour-profiles/ beside the config"));
    layout->addWidget(list_);
    hint_->setObjectName("profileHint");
    hint_->setWordWrap(true);
    layout->addWidget(hint_);
    auto* row = new QHBoxLayout;
    QPushButton* save = colourTabButton(tr("Save as…"), tr("Save the config's colours as a profile under a name"), "saveProfile", this);
    QPushButton* load = colourTabButton(tr("Load"), tr("The selected profile's colours replace the config's (one undo step)"),
                               "loadProfile", this);
    QPushButton* remove = colourTabButton(tr("Delete"), tr("Delete the selected profile's file"), "deleteProfile", this);
    QPushButton* compare = colourTabButton(tr("Compare…"),
                                  tr("The selected profile against the config's colours: ranges side by side and the "
                                     "pixels of the frame on screen that change class"),
                                  "compareProfile", this);
    for (QPushButton* b : {save, load, remove, compare}) row->addWidget(b);
    layout->addLayout(row);

    auto needSelection = [this](const std::function<std::optional<QString>(const QString&)>& act) {
        const QString path = selectedPath();
        if (path.isEmpty()) {
            emit message(tr("Select a profile in the list first"));
            return;
        }
        if (const auto why = act(path)) emit message(*why);
    };
    connect(save, &QPushButton::clicked, this, &ColourProfilesBox::askSave);
    connect(load, &QPushButton::clicked, this, [this, needSelection] { needSelection([this](const QString& p) { return loadProfile(p); }); });
    connect(compare, &QPushButton::clicked, this,
            [this, needSelection] { needSelection([this](const QString& p) { return compareProfile(p); }); });
    connect(remove, &QPushButton::clicked, this, [this, needSelection] {
        needSelection([this](const QString& p) -> std::optional<QString> {
            if (QMessageBox::question(this, tr("Delete profile"), tr("Delete the profile file %1?").arg(p)) != QMessageBox::Yes)
                return std::nullopt;
            return deleteProfile(p);
        });
    });
    connect(list_, &QListWidget::itemDoubleClicked, this, [this] { if (const auto why = loadProfile(selectedPath())) emit message(*why); });
    connect(doc_, &ConfigDocument::pathChanged, this, [this] { refreshList(); });
    refreshList();
}

QString ColourProfilesBox::folder() const
{
    return doc_->path().isEmpty() ? QString() : qs(colourProfileFolder(doc_->path().toStdString()));
}

QString ColourProfilesBox::selectedPath() const
{
    const QListWidgetItem* item = list_->currentItem();
    return item ? item->data(Qt::UserRole).toString() : QString();
}

void ColourProfilesBox::refreshList()
{
    const QString keep = selectedPath();
    list_->clear();
    const QString dir = folder();
    if (dir.isEmpty()) {
        hint_->setText(tr("Save the config to a file first: profiles live beside it."));
        return;
    }
    const auto entries = listColourProfiles(dir.toStdString());
    for (const ColourProfileEntry& e : entries) {
        const QString file = QFileInfo(qs(e.path)).fileName();
        auto* item = new QListWidgetItem(e.error ? tr("%1 (does not load)").arg(file) : qs(e.name), list_);
        item->setData(Qt::UserRole, qs(e.path));
        item->setToolTip(e.error ? qs(e.error->toString()) : qs(e.path));
        if (e.error) item->setForeground(QColor(170, 0, 0));
        if (qs(e.path) == keep) list_->setCurrentItem(item);
    }
    hint_->setText(entries.empty() ? tr("No profiles yet beside this config: Save as… makes one.")
                                   : tr("%n profile(s) in colour-profiles/ beside the config", nullptr, int(entries.size())));
    hint_->setToolTip(dir);
}

std::optional<QString> ColourProfilesBox::saveProfile(const QString& name)
{
    const QString dir = folder();
    if (dir.isEmpty()) return tr("Save the config to a file first: profiles live beside it (colour-profiles/)");
    const ColourProfileSave saved =
        saveColourProfile(dir.toStdString(), ColourProfile{name.trimmed().toStdString(), doc_->config().colors});
    if (saved.error) return tr("Profile not saved: %1").arg(qs(saved.error->toString()));
    refreshList();
    for (int i = 0; i < list_->count(); ++i)
        if (list_->item(i)->data(Qt::UserRole).toString() == qs(saved.path)) list_->setCurrentRow(i);
    emit message(tr("Saved the colours as profile \"%1\" (%2)").arg(name.trimmed(), qs(saved.path)));
    return std::nullopt;
}

std::optional<QString> ColourProfilesBox::loadProfile(const QString& path)
{
    if (path.isEmpty()) return tr("Select a profile in the list first");
    const ColourProfileLoad load = loadColourProfile(path.toStdString());
    if (!load.ok()) return tr("Profile not loaded: %1").arg(qs(load.error->toString()));
    Config next = doc_->config();
    next.colors = load.profile.colors;
    next.colors.sampleOutlierPct = doc_->config().colors.sampleOutlierPct;  // the tab's setting, not the venue's
    if (const auto why = doc_->replaceConfig(next, tr("Load colour profile %1").arg(qs(load.profile.name))))
        return tr("Profile %1 not loaded: %2").arg(path, *why);
    emit message(tr("Loaded colour profile \"%1\" (Undo restores the colours before)").arg(qs(load.profile.name)));
    return std::nullopt;
}

std::optional<QString> ColourProfilesBox::deleteProfile(const QString& path)
{
    std::error_code ec;
    if (!std::filesystem::remove(path.toStdString(), ec) || ec)
        return tr("%1: not deleted: %2").arg(path, ec ? qs(ec.message()) : tr("no such file"));
    refreshList();
    emit message(tr("Deleted the profile file %1").arg(path));
    return std::nullopt;
}

std::optional<QString> ColourProfilesBox::compareProfile(const QString& path)
{
    if (path.isEmpty()) return tr("Select a profile in the list first");
    const ColourProfileLoad load = loadColourProfile(path.toStdString());
    if (!load.ok()) return tr("Profile not compared: %1").arg(qs(load.error->toString()));
    ColourDiffView::Frame frame;
    if (run_ && run_->error.isEmpty() && run_->result.ok()) {
        frame.raw = run_->frame;
        frame.format = run_->format;
        frame.acquired = run_->result.stages.acquired;
        frame.config = run_->config;
        frame.index = run_->frameIndex;
    }
    if (diff_) diff_->deleteLater();
    diff_ = new ColourDiffView(tr("config"), doc_->config().colors, tr("profile \"%1\"").arg(qs(load.profile.name)),
                               load.profile.colors, frame, this);
    diff_->setAttribute(Qt::WA_DeleteOnClose, false);
    diff_->show();
    return std::nullopt;
}

void ColourProfilesBox::askSave()
{
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Save colour profile"),
                                               tr("Name of the profile (e.g. \"venue field A\"):"), QLineEdit::Normal,
                                               QString(), &ok);
    if (!ok || name.trimmed().isEmpty()) return;
    if (const auto file = colourProfileFileName(name.trimmed().toStdString())) {
        const QString path = folder() + QStringLiteral("/") + qs(*file);
        if (!folder().isEmpty() && QFileInfo::exists(path) &&
            QMessageBox::question(this, tr("Save colour profile"), tr("%1 exists. Replace it?").arg(path)) != QMessageBox::Yes)
            return;
    }
    if (const auto why = saveProfile(name)) emit message(*why);
}

}  // namespace omnitune
