#include "widgets/ConfigFiles.h"

#include "widgets/ConfigDocument.h"
#include "widgets/NoticeBar.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>

namespace omnitune {

ConfigFiles::ConfigFiles(ConfigDocument* doc, NoticeBar* notices, QWidget* window)
    : QObject(window), doc_(doc), notices_(notices), window_(window), origin_(tr("default config"))
{
}

bool ConfigFiles::open(const QString& path)
{
    QStringList warnings;
    if (const auto err = doc_->load(path, &warnings)) {
        QMessageBox::critical(window_, tr("Cannot load the config"), *err);
        return false;
    }
    sessionConfigPath_.clear();
    builtInDefaults_ = false;
    notices_->add(tr("Config %1 loaded with warnings (omnitune-config --upgrade FILE writes the missing keys):").arg(path),
                  warnings);
    return true;
}

bool ConfigFiles::showsBuiltInDefaults() const { return builtInDefaults_ && doc_->path().isEmpty(); }

bool ConfigFiles::openSessionConfig(const QString& path)
{
    if (!open(path)) return false;
    sessionConfigPath_ = path;
    return true;
}

void ConfigFiles::keepFor(const QString& name, const QString& path, const QString& sessionFolder)
{
    const QString dir = sessionFolder.isEmpty() ? QFileInfo(path).absolutePath() : sessionFolder;
    suggestedPath_ = QDir(dir).filePath(QStringLiteral("config.yml"));
    const QString what = sessionFolder.isEmpty() ? tr("%1 carries no config").arg(name) : tr("%1 has no config.yml").arg(name);
    QString note;
    if (!doc_->path().isEmpty() && doc_->path() == sessionConfigPath_) {
        origin_ = tr("config of %1").arg(QFileInfo(doc_->path()).absoluteDir().dirName());
        note = tr("showing the %1 (%2), not linked to that file: Save config (Ctrl+S) asks where, proposing %3")
                   .arg(origin_, doc_->path(), suggestedPath_);
        doc_->reset(doc_->config());  // same values, no file
    } else if (doc_->path().isEmpty()) {
        note = tr("showing the %1; Save config (Ctrl+S) asks where, proposing %2").arg(origin_, suggestedPath_);
    } else {
        note = tr("still using %1, which is not the previous session's own; Save config (Ctrl+S) writes there").arg(doc_->path());
    }
    sessionConfigPath_.clear();
    notices_->add(tr("Config:"), {tr("%1: %2.").arg(what, note)});
}

bool ConfigFiles::save()
{
    if (doc_->path().isEmpty()) return saveAs();
    if (const auto err = doc_->save()) {
        QMessageBox::critical(window_, tr("Cannot save the config"), *err);
        return false;
    }
    builtInDefaults_ = false;
    emit message(tr("Saved %1 (the file as it was before your first save is kept as .bak)").arg(doc_->path()));
    return true;
}

bool ConfigFiles::saveAs()
{
    const QString proposed = doc_->path().isEmpty() ? suggestedPath_ : doc_->path();
    const QString path = QFileDialog::getSaveFileName(window_, tr("Save config"), proposed, tr("Config (*.yml *.yaml)"));
    if (path.isEmpty()) return false;
    if (const auto err = doc_->saveAs(path)) {
        QMessageBox::critical(window_, tr("Cannot save the config"), *err);
        return false;
    }
    builtInDefaults_ = false;
    return true;
}

bool ConfigFiles::maybeSave(const QString& question, bool discardNow)
{
    if (!doc_->isDirty()) return true;
    const auto answer = QMessageBox::warning(window_, tr("Unsaved changes"), question,
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    if (answer != QMessageBox::Discard) return false;
    if (discardNow) doc_->discardChanges();  // the edits must not go on with the next source
    return true;
}

QString ConfigFiles::choose()
{
    if (!maybeSave(tr("The config has unsaved changes. Save them before opening another?"), false)) return {};
    const QString path = QFileDialog::getOpenFileName(window_, tr("Open config"), QString(), tr("Config (*.yml *.yaml)"));
    return !path.isEmpty() && open(path) ? path : QString();
}

QString ConfigFiles::name() const { return doc_->path().isEmpty() ? origin_ : QFileInfo(doc_->path()).fileName(); }

}  // namespace omnitune
