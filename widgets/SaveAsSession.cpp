#include "widgets/SaveAsSession.h"

#include "calib/session/SessionExport.h"
#include "calib/source/FrameSourceFactory.h"
#include "core/Progress.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>

#include <cmath>

namespace omnitune {

namespace {

// core's progress-and-cancel interface on a window-modal progress dialog: setValue() lets the
// dialog's Cancel through between frames.
class DialogProgress : public Progress {
public:
    explicit DialogProgress(QProgressDialog& dialog) : dialog_(dialog) {}
    void update(double percent) override { dialog_.setValue(int(std::lround(percent))); }
    bool isCancelRequested() const override { return dialog_.wasCanceled(); }

private:
    QProgressDialog& dialog_;
};

}  // namespace

SaveAsSession::SaveAsSession(QWidget* parent) : QObject(parent), parentWidget_(parent)
{
    ask_ = [this](const QString& suggested) {
        return QFileDialog::getSaveFileName(parentWidget_, tr("Save as session: a new folder for the frames"), suggested,
                                            QString(), nullptr, QFileDialog::ShowDirsOnly);
    };
}

QString SaveAsSession::save(const QString& sourcePath, const Config& config)
{
    if (sourcePath.isEmpty()) return {};
    const QFileInfo source(sourcePath);
    // Beside the source: "run3" becomes "run3-session".
    const QString base = source.isDir() ? source.absoluteFilePath() : source.absolutePath() + "/" + source.completeBaseName();
    const QString folder = ask_(base + "-session");
    if (folder.isEmpty()) return {};

    auto opened = openFrameSource(sourcePath.toStdString());
    if (!opened.ok()) {
        QMessageBox::warning(parentWidget_, tr("Save as session"), QString::fromStdString(opened.error));
        return {};
    }
    QProgressDialog dialog(tr("Writing the frames of %1 to %2...").arg(source.fileName(), folder), tr("Cancel"), 0, 100,
                           parentWidget_);
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(500);  // a handful of frames needs no dialog
    DialogProgress progress(dialog);
    const SessionExportResult r = exportSession(*opened.source, folder.toStdString(), config, {}, &progress);
    dialog.reset();
    parentWidget_->activateWindow();  // the keys (T to mark) go to the window again, not to nowhere
    if (!r.ok()) {
        QMessageBox::warning(parentWidget_, tr("Save as session"),
                             tr("The session could not be saved: %1").arg(QString::fromStdString(r.error->toString())));
        return {};
    }
    if (r.cancelled) {
        emit message(tr("Save as session cancelled: %1 holds the %2 frame(s) written so far").arg(folder).arg(r.frames));
        return {};
    }
    QString text = tr("Saved %1 frame(s) as the session %2").arg(r.frames).arg(folder);
    if (!r.configNote.empty()) text += "; " + QString::fromStdString(r.configNote);
    if (!r.skipped.empty())
        text += tr("; %1 unreadable frame(s) left out, the first: %2").arg(r.skipped.size()).arg(QString::fromStdString(r.skipped.front()));
    emit message(text);
    return folder;
}

}  // namespace omnitune
