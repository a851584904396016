#include "widgets/RecoveryOffer.h"

#include "widgets/ConfigDocument.h"
#include "widgets/RecoveryFile.h"

#include <QAbstractButton>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>

namespace omnitune {

namespace {

constexpr int kListedChanges = 15;  // more would push the buttons off a laptop screen

}  // namespace

QStringList offerRecovery(QWidget* parent, RecoveryFile& recovery, const ConfigDocument& doc)
{
    const auto edits = recovery.pending(doc.path(), doc.config());
    if (!edits) return {};
    if (!edits->error.isEmpty())
        return {QObject::tr("A crash-recovery file for this config cannot be read, so it is kept as it is: %1")
                    .arg(edits->error)};

    QStringList lines;
    for (const ConfigChange& c : edits->changes) {
        if (lines.size() == kListedChanges) {
            lines << QObject::tr("... and %1 more").arg(int(edits->changes.size()) - kListedChanges);
            break;
        }
        lines << QString::fromStdString(c.toString());
    }
    const QFileInfo file(doc.path());
    const QString config = doc.path().isEmpty() ? QObject::tr("the default config") : file.fileName();
    const QString where = doc.path().isEmpty() ? QString() : QObject::tr(" in %1").arg(file.absolutePath());
    QMessageBox box(QMessageBox::Question, QObject::tr("Recover unsaved edits"),
                    QObject::tr("OmniTune ended without saving %1 edit(s) of %2%3 (last kept %4). Restore them?")
                        .arg(edits->changes.size())
                        .arg(config, where, QLocale().toString(edits->written, QLocale::ShortFormat)),
                    QMessageBox::Yes | QMessageBox::Discard | QMessageBox::Cancel, parent);
    box.setInformativeText(QObject::tr("Saved \u2192 recovered:\n") + lines.join('\n'));
    box.button(QMessageBox::Yes)->setText(QObject::tr("Restore"));
    box.button(QMessageBox::Discard)->setText(QObject::tr("Discard them"));
    box.button(QMessageBox::Cancel)->setText(QObject::tr("Not now"));
    box.setDefaultButton(QMessageBox::Yes);
    box.setEscapeButton(QMessageBox::Cancel);  // Escape keeps the file for later
    const int answer = box.exec();
    if (answer == QMessageBox::Discard) {
        recovery.drop(*edits);
        return {};
    }
    if (answer != QMessageBox::Yes) return {};
    const QStringList refused = recovery.restore(*edits);
    QStringList out{QObject::tr("Restored %1 recovered edit(s) of %2; they are not saved yet (Ctrl+Z takes them back)")
                        .arg(int(edits->changes.size()) - refused.size())
                        .arg(config)};
    for (const QString& r : refused) out << QObject::tr("Not restored: %1").arg(r);
    return out;
}

}  // namespace omnitune
